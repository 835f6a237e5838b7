// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_erf.h"

#include <cmath>

inline namespace edgetrack_ports {

double vnl_erfc(double x) { return std::erfc(x); }

}  // inline namespace edgetrack_ports
