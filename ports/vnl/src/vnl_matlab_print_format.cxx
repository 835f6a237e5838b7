// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matlab_print_format.h"

#include <iostream>
#include <vector>

inline namespace edgetrack_ports {

namespace {
// Process-wide, as upstream's (see the header).
vnl_matlab_print_format current_format = vnl_matlab_print_format_short;
std::vector<vnl_matlab_print_format>& format_stack() {
  static std::vector<vnl_matlab_print_format> stack;
  return stack;
}
}  // namespace

vnl_matlab_print_format vnl_matlab_print_format_top() { return current_format; }

vnl_matlab_print_format vnl_matlab_print_format_set(vnl_matlab_print_format f) {
  const vnl_matlab_print_format old = current_format;
  current_format = f;
  return old;
}

void vnl_matlab_print_format_push(vnl_matlab_print_format f) {
  format_stack().push_back(current_format);
  current_format = f;
}

void vnl_matlab_print_format_pop() {
  if (format_stack().empty()) {
    std::cerr << "vnl_matlab_print_format_pop: format stack empty\n";
    return;
  }
  current_format = format_stack().back();
  format_stack().pop_back();
}

}  // inline namespace edgetrack_ports
