// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_matlab_filewrite.h: a MATLAB level-4 .mat file written one
/// variable at a time (vnl_matlab_write); a variable without a name is called basename
/// followed by 0, 1, 2... (basename "targetvar" by default, as upstream).
#pragma once

#ifdef vnl_matlab_filewrite_h_
#error "edgetrack's drop-in vnl/vnl_matlab_filewrite.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <complex>
#include <fstream>
#include <string>

#include "vnl/vnl_matrix.h"
#include "vnl/vnl_vector.h"

inline namespace edgetrack_ports {

class vnl_matlab_filewrite {
 public:
  /// Opens (truncates) file_name for writing; a message on std::cerr if that fails.
  explicit vnl_matlab_filewrite(const char* file_name, const char* basename = nullptr);

  void write(double v, const char* variable_name = nullptr);
  void write(const vnl_vector<double>& v, const char* variable_name = nullptr);
  void write(const vnl_vector<std::complex<double>>& v, const char* variable_name = nullptr);
  void write(const vnl_matrix<float>& M, const char* variable_name = nullptr);
  void write(const vnl_matrix<double>& M, const char* variable_name = nullptr);
  void write(const vnl_matrix<std::complex<float>>& M, const char* variable_name = nullptr);
  void write(const vnl_matrix<std::complex<double>>& M, const char* variable_name = nullptr);
  void write(const double* const* M, int rows, int cols, const char* variable_name = nullptr);

 protected:
  std::string basename_;
  int variable_int_ = 0;
  std::fstream out_;

  std::string make_var_name(const char* variable_name);
};

}  // inline namespace edgetrack_ports
