// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_algo_fwd.h: forward declarations of the vnl_algo classes.
#pragma once

#ifdef vnl_algo_fwd_h_
#error "edgetrack's drop-in vnl/algo/vnl_algo_fwd.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

template <class T>
class vnl_svd;
template <class T>
class vnl_svd_economy;
template <class T, unsigned R, unsigned C>
class vnl_svd_fixed;
template <class T>
class vnl_qr;
template <class T>
class vnl_cholesky_of;
using vnl_cholesky = vnl_cholesky_of<double>;
template <class T>
class vnl_symmetric_eigensystem;
template <class T>
struct vnl_matrix_inverse;
class vnl_simpson_integral;
class vnl_adaptsimpson_integral;
struct vnl_amoeba_SimplexCorner;
class vnl_complex_eigensystem;
class vnl_conjugate_gradient;
class vnl_cpoly_roots;
class vnl_lbfgs;
class vnl_levenberg_marquardt;

}  // inline namespace edgetrack_ports
