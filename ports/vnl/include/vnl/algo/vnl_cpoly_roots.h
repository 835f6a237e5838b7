// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_cpoly_roots.h: the N roots of the monic complex polynomial
/// t^N + a[0] t^(N-1) + ... + a[N-1], in `solns`. Ours: Aberth-Ehrlich simultaneous iteration
/// from points on a circle bounding the roots, then one Newton step each (upstream: eigenvalues
/// of the companion matrix). The order of the roots is not upstream's.
#pragma once

#ifdef vnl_cpoly_roots_h_
#error "edgetrack's drop-in vnl/algo/vnl_cpoly_roots.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>

#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_cpoly_roots {
 public:
  explicit vnl_cpoly_roots(const vnl_vector<std::complex<double>>& a);
  vnl_cpoly_roots(const vnl_vector<double>& a_real, const vnl_vector<double>& a_imag);

  vnl_vector<std::complex<double>> solns;

 private:
  unsigned N;
  void compute(const vnl_vector<std::complex<double>>& a);
};

}  // inline namespace edgetrack_ports
