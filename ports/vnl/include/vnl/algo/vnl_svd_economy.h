// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_svd_economy.h: only the singular values (lambdas, in
/// descending order) and the right singular vectors V of M, from our vnl_svd.
#pragma once

#ifdef vnl_svd_economy_h_
#error "edgetrack's drop-in vnl/algo/vnl_svd_economy.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include "vnl/algo/vnl_svd.h"
#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

template <class real_t>
class vnl_svd_economy {
 public:
  using singval_t = typename vnl_numeric_traits<real_t>::abs_t;

  explicit vnl_svd_economy(const vnl_matrix<real_t>& M)
      : m_(static_cast<long>(M.rows())), n_(static_cast<long>(M.cols())) {
    const vnl_svd<real_t> svd(M);
    V_ = svd.V();
    sv_ = svd.W().diagonal();
  }
  const vnl_matrix<real_t>& V() const { return V_; }
  vnl_matrix<real_t>& V() { return V_; }
  const vnl_vector<singval_t>& lambdas() const { return sv_; }
  vnl_vector<singval_t>& lambdas() { return sv_; }
  /// The right singular vector of the smallest singular value.
  vnl_vector<real_t> nullvector() { return V_.get_column(static_cast<std::size_t>(n_ - 1)); }

 protected:
  long m_, n_;
  vnl_matrix<real_t> V_;
  vnl_vector<singval_t> sv_;
};

}  // inline namespace edgetrack_ports
