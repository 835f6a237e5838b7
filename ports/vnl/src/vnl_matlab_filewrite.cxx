// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_matlab_filewrite.h"

#include <iostream>

#include "vnl/vnl_matlab_write.h"

inline namespace edgetrack_ports {

vnl_matlab_filewrite::vnl_matlab_filewrite(const char* file_name, const char* basename)
    : basename_(basename ? basename : "targetvar") {
  out_.open(file_name, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!out_) std::cerr << "vnl_matlab_filewrite: cannot open " << file_name << " for writing\n";
}

std::string vnl_matlab_filewrite::make_var_name(const char* variable_name) {
  return variable_name ? std::string(variable_name) : basename_ + std::to_string(variable_int_++);
}

void vnl_matlab_filewrite::write(double v, const char* variable_name) {
  vnl_matlab_write(out_, v, make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_vector<double>& v, const char* variable_name) {
  vnl_matlab_write(out_, v.data_block(), static_cast<unsigned>(v.size()), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_vector<std::complex<double>>& v, const char* variable_name) {
  vnl_matlab_write(out_, v.data_block(), static_cast<unsigned>(v.size()), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_matrix<float>& M, const char* variable_name) {
  vnl_matlab_write(out_, M.data_array(), M.rows(), M.cols(), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_matrix<double>& M, const char* variable_name) {
  vnl_matlab_write(out_, M.data_array(), M.rows(), M.cols(), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_matrix<std::complex<float>>& M, const char* variable_name) {
  vnl_matlab_write(out_, M.data_array(), M.rows(), M.cols(), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const vnl_matrix<std::complex<double>>& M, const char* variable_name) {
  vnl_matlab_write(out_, M.data_array(), M.rows(), M.cols(), make_var_name(variable_name).c_str());
}

void vnl_matlab_filewrite::write(const double* const* M, int rows, int cols, const char* variable_name) {
  vnl_matlab_write(out_, M, static_cast<unsigned>(rows), static_cast<unsigned>(cols),
                   make_var_name(variable_name).c_str());
}

}  // inline namespace edgetrack_ports
