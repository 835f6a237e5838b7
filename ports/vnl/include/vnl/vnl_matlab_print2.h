// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_print2.h: vnl_matlab_print(x, name, format) as a value
/// for operator<<, so `std::cerr << vnl_matlab_print(M, "M")` prints like
/// `vnl_matlab_print(std::cerr, M, "M")`.
#pragma once

#ifdef vnl_matlab_print2_h_
#error "edgetrack's drop-in vnl/vnl_matlab_print2.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <ostream>

#include "vnl/vnl_matlab_print.h"

inline namespace edgetrack_ports {

template <class T>
struct vnl_matlab_print_proxy {
  const T& obj;
  const char* name;
  vnl_matlab_print_format format;
  vnl_matlab_print_proxy(const T& obj_, const char* name_, vnl_matlab_print_format format_)
      : obj(obj_), name(name_), format(format_) {}
};

template <class T>
std::ostream& operator<<(std::ostream& os, const vnl_matlab_print_proxy<T>& mp) {
  return vnl_matlab_print(os, mp.obj, mp.name, mp.format);
}

template <class T>
vnl_matlab_print_proxy<T> vnl_matlab_print(const T& obj, const char* name = nullptr,
                                           vnl_matlab_print_format format = vnl_matlab_print_format_default) {
  return vnl_matlab_print_proxy<T>(obj, name, format);
}

}  // inline namespace edgetrack_ports
