// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_numeric_traits.h: for each scalar, zero, one and maxval, and the
/// types vnl computes norms in (abs_t), accumulates in (double_t) and divides in (real_t).
/// Upstream's choices: int's abs_t is unsigned int and its real_t double; float's real_t is
/// double; complex<T>'s abs_t is T. Our fixed-point scalars are their own abs_t, double_t and
/// real_t, so vnl never leaves fixed point for them.
#pragma once

#ifdef vnl_numeric_traits_h_
#error "edgetrack's drop-in vnl/vnl_numeric_traits.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "real/fixed64.h"

inline namespace edgetrack_ports {

template <class T>
class vnl_numeric_traits;

namespace vnl_numeric_traits_detail {
template <class T, class Abs, class Double>
struct integral {
  static constexpr T zero = T(0);
  static constexpr T one = T(1);
  static constexpr T maxval = std::numeric_limits<T>::max();
  using abs_t = Abs;
  using double_t = Double;
  using real_t = double;
  using self = T;
  using signed_t = std::make_signed_t<T>;
};
template <class T, class Double, class Real>
struct floating {
  static constexpr T zero = T(0);
  static constexpr T one = T(1);
  static constexpr T maxval = std::numeric_limits<T>::max();
  using abs_t = T;
  using double_t = Double;
  using real_t = Real;
  using self = T;
  using signed_t = T;
};
}  // namespace vnl_numeric_traits_detail

template <>
class vnl_numeric_traits<bool> {
 public:
  static constexpr bool zero = false;
  static constexpr bool one = true;
  static constexpr bool maxval = true;
  using abs_t = unsigned int;
  using double_t = unsigned int;
  using real_t = double;
  using self = bool;
  using signed_t = bool;
};
template <>
class vnl_numeric_traits<char> : public vnl_numeric_traits_detail::integral<char, unsigned char, short> {};
template <>
class vnl_numeric_traits<signed char> : public vnl_numeric_traits_detail::integral<signed char, unsigned char, short> {
};
template <>
class vnl_numeric_traits<unsigned char>
    : public vnl_numeric_traits_detail::integral<unsigned char, unsigned char, unsigned short> {};
template <>
class vnl_numeric_traits<short> : public vnl_numeric_traits_detail::integral<short, unsigned short, int> {};
template <>
class vnl_numeric_traits<unsigned short>
    : public vnl_numeric_traits_detail::integral<unsigned short, unsigned short, unsigned int> {};
template <>
class vnl_numeric_traits<int> : public vnl_numeric_traits_detail::integral<int, unsigned int, long long> {};
template <>
class vnl_numeric_traits<unsigned int>
    : public vnl_numeric_traits_detail::integral<unsigned int, unsigned int, unsigned long long> {};
template <>
class vnl_numeric_traits<long> : public vnl_numeric_traits_detail::integral<long, unsigned long, long long> {};
template <>
class vnl_numeric_traits<unsigned long>
    : public vnl_numeric_traits_detail::integral<unsigned long, unsigned long, unsigned long long> {};
template <>
class vnl_numeric_traits<long long>
    : public vnl_numeric_traits_detail::integral<long long, unsigned long long, long long> {};
template <>
class vnl_numeric_traits<unsigned long long>
    : public vnl_numeric_traits_detail::integral<unsigned long long, unsigned long long, unsigned long long> {};
template <>
class vnl_numeric_traits<float> : public vnl_numeric_traits_detail::floating<float, double, double> {};
template <>
class vnl_numeric_traits<double> : public vnl_numeric_traits_detail::floating<double, long double, double> {};
template <>
class vnl_numeric_traits<long double>
    : public vnl_numeric_traits_detail::floating<long double, long double, long double> {};

template <class T>
class vnl_numeric_traits<std::complex<T>> {
 public:
  static inline const std::complex<T> zero = std::complex<T>(0, 0);
  static inline const std::complex<T> one = std::complex<T>(1, 0);
  static inline const std::complex<T> maxval = std::complex<T>(vnl_numeric_traits<T>::maxval, 0);
  using abs_t = T;
  using double_t = std::complex<typename vnl_numeric_traits<T>::double_t>;
  using real_t = std::complex<T>;
  using self = std::complex<T>;
  using signed_t = std::complex<T>;
};

template <int F>
class vnl_numeric_traits<fixedpoint::fixed64<F>> {
 public:
  using self = fixedpoint::fixed64<F>;
  static inline const self zero = self(0);
  static inline const self one = self(1);
  static inline const self maxval = std::numeric_limits<self>::max();
  using abs_t = self;
  using double_t = self;
  using real_t = self;
  using signed_t = self;
};

template <class T>
class vnl_numeric_traits<const T> : public vnl_numeric_traits<T> {};

}  // inline namespace edgetrack_ports
