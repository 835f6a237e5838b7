// SPDX-License-Identifier: BSD-3-Clause
/// Definitions for vnl_polynomial.h (upstream: core/vnl/vnl_polynomial.hxx).
#pragma once

#include <ostream>
#include <type_traits>

#include "vnl/vnl_polynomial.h"

inline namespace edgetrack_ports {

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::operator-() const {
  std::vector<T> c(coeffs_);
  for (T& x : c) x = -x;
  return vnl_polynomial(c);
}

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::operator+(const vnl_polynomial& f) const {
  std::vector<T> c(coeffs_.size() > f.coeffs_.size() ? coeffs_ : f.coeffs_);
  const std::vector<T>& shorter = coeffs_.size() > f.coeffs_.size() ? f.coeffs_ : coeffs_;
  for (std::size_t i = 0; i < shorter.size(); ++i) c[i] += shorter[i];
  return vnl_polynomial(c);
}

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::operator*(const vnl_polynomial& f) const {
  if (coeffs_.empty() || f.coeffs_.empty()) return vnl_polynomial();
  std::vector<T> c(coeffs_.size() + f.coeffs_.size() - 1, T(0));
  for (std::size_t i = 0; i < coeffs_.size(); ++i) {
    for (std::size_t j = 0; j < f.coeffs_.size(); ++j) c[i + j] += coeffs_[i] * f.coeffs_[j];
  }
  return vnl_polynomial(c);
}

namespace vnl_polynomial_detail {
/// Long division of a by b (b nonzero): the quotient and the remainder.
template <class T>
void divide(const std::vector<T>& a, const std::vector<T>& b, std::vector<T>& quotient, std::vector<T>& remainder) {
  assert(!b.empty());
  remainder = a;
  if (a.size() < b.size()) {
    quotient.clear();
    return;
  }
  quotient.assign(a.size() - b.size() + 1, T(0));
  for (std::size_t k = quotient.size(); k-- > 0;) {
    const T factor = remainder[k + b.size() - 1] / b.back();
    quotient[k] = factor;
    for (std::size_t j = 0; j < b.size(); ++j) remainder[k + j] -= factor * b[j];
  }
  remainder.resize(b.size() - 1);
}
}  // namespace vnl_polynomial_detail

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::operator/(const vnl_polynomial& f) const {
  std::vector<T> q, r;
  vnl_polynomial_detail::divide(coeffs_, f.coeffs_, q, r);
  return vnl_polynomial(q);
}

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::operator%(const vnl_polynomial& f) const {
  std::vector<T> q, r;
  vnl_polynomial_detail::divide(coeffs_, f.coeffs_, q, r);
  return vnl_polynomial(r);
}

template <class T>
T vnl_polynomial<T>::evaluate(const T& x) const {
  T total(0);
  for (std::size_t i = coeffs_.size(); i-- > 0;) total = total * x + coeffs_[i];
  return total;
}

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::derivative() const {
  std::vector<T> c;
  for (std::size_t i = 1; i < coeffs_.size(); ++i) c.push_back(coeffs_[i] * T(static_cast<int>(i)));
  return vnl_polynomial(c);
}

template <class T>
vnl_polynomial<T> vnl_polynomial<T>::primitive() const {
  std::vector<T> c(coeffs_.size() + 1, T(0));
  for (std::size_t i = 0; i < coeffs_.size(); ++i) c[i + 1] = coeffs_[i] / T(static_cast<int>(i + 1));
  return vnl_polynomial(c);
}

namespace vnl_polynomial_detail {
template <class T>
struct is_fixed_point : std::false_type {};
template <int F>
struct is_fixed_point<fixedpoint::fixed64<F>> : std::true_type {};

/// A coefficient as its own << prints it (vnl_rational as 1/2, as upstream); fixed point as a
/// double (I/O only).
template <class T>
void print_value(std::ostream& os, const T& x) {
  if constexpr (is_fixed_point<T>::value) {
    os << static_cast<double>(x);
  } else {
    os << x;
  }
}
}  // namespace vnl_polynomial_detail

template <class T>
void vnl_polynomial<T>::print(std::ostream& os) const {
  bool first = true;
  for (int i = degree(); i >= 0; --i) {
    const T a = coeffs_[static_cast<std::size_t>(i)];
    if (a == T(0)) continue;
    os << ' ';
    if (a > T(0) && !first) os << '+';
    if (i == 0) {
      vnl_polynomial_detail::print_value(os, a);
    } else if (a == -T(1)) {
      os << '-';
    } else if (a != T(1)) {
      vnl_polynomial_detail::print_value(os, a);
      os << ' ';
    }
    if (i == 1) {
      os << 'X';
    } else if (i > 1) {
      os << "X^" << i;
    }
    first = false;
  }
  if (first) os << " 0";
}

template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_polynomial<T>& p) {
  p.print(os);
  return os;
}

#define VNL_POLYNOMIAL_INSTANTIATE(T) \
  template class vnl_polynomial<T>;   \
  template std::ostream& operator<<(std::ostream&, const vnl_polynomial<T>&)

}  // inline namespace edgetrack_ports
