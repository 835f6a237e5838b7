// SPDX-License-Identifier: BSD-3-Clause
/// Instantiates vnl_least_squares_function_of for double and defines upstream's
/// vnl_least_squares_function on it.
#include <iostream>

#include "vnl/vnl_least_squares_function.hxx"

inline namespace edgetrack_ports {

VNL_LEAST_SQUARES_FUNCTION_INSTANTIATE(double);

vnl_least_squares_function::vnl_least_squares_function(unsigned int number_of_unknowns,
                                                       unsigned int number_of_residuals, UseGradient g)
    : vnl_least_squares_function_of<double>(number_of_unknowns, number_of_residuals, g) {
  if (number_of_unknowns > number_of_residuals) {
    std::cerr << "vnl_least_squares_function: WARNING: unknowns(" << number_of_unknowns << ") > residuals("
              << number_of_residuals << ")\n";
  }
}

}  // inline namespace edgetrack_ports
