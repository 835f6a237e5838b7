// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_nonlinear_minimizer.h"

#include <iomanip>
#include <iostream>

inline namespace edgetrack_ports {

void vnl_nonlinear_minimizer_print_iteration(int iterations, int evaluations, double best_f) {
  std::cerr << "Iter " << std::setw(4) << iterations << ", Eval " << std::setw(4) << evaluations
            << ": Best F = " << std::setw(10) << best_f << '\n';
}

}  // inline namespace edgetrack_ports
