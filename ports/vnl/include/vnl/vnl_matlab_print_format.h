// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_print_format.h: the number formats of vnl_matlab_print
/// (MATLAB's "format short", "format long" and their e forms) and the default format, kept
/// as upstream in one process-wide stack (not thread-safe); it starts at short.
#pragma once

#ifdef vnl_matlab_print_format_h_
#error "edgetrack's drop-in vnl/vnl_matlab_print_format.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

enum vnl_matlab_print_format {
  vnl_matlab_print_format_default,  // whatever the top of the stack says
  vnl_matlab_print_format_short,
  vnl_matlab_print_format_long,
  vnl_matlab_print_format_short_e,
  vnl_matlab_print_format_long_e
};

/// The current default format.
vnl_matlab_print_format vnl_matlab_print_format_top();
/// Replaces the current default; returns the one it replaced.
vnl_matlab_print_format vnl_matlab_print_format_set(vnl_matlab_print_format);
/// Makes f the default, remembering the previous one for pop().
void vnl_matlab_print_format_push(vnl_matlab_print_format f);
/// Restores the default before the last push (a message on std::cerr if there was none).
void vnl_matlab_print_format_pop();

}  // inline namespace edgetrack_ports
