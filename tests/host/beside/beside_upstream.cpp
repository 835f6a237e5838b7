// SPDX-License-Identifier: BSD-3-Clause
/// The half that uses Debian's real ViSP: its vpImage and vpImageIo, from /usr/include.
#include <visp3/core/vpImage.h>
#include <visp3/io/vpImageIo.h>

#include "beside.h"

long upstream_pgm_round_trip(const std::string& pgm_path, unsigned rows, unsigned cols) {
  vpImage<unsigned char> written(rows, cols);
  for (unsigned i = 0; i < rows; ++i)
    for (unsigned j = 0; j < cols; ++j) written[i][j] = static_cast<unsigned char>(i + 2 * j);
  vpImageIo::write(written, pgm_path);
  vpImage<unsigned char> read;
  vpImageIo::read(read, pgm_path);
  if (read.getHeight() != rows || read.getWidth() != cols) return -1;
  long sum = 0;
  for (unsigned i = 0; i < rows; ++i)
    for (unsigned j = 0; j < cols; ++j) sum += read[i][j];
  return sum;
}
