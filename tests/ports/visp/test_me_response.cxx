// SPDX-License-Identifier: BSD-3-Clause
/// MaskResponse: every way of reading a response (at, at_each, at_each_in_box, at_block_3x3 and,
/// on x86-64 with AVX2, path_each_5_avx2),
/// with each choice of kernels (real/vector_kernels.h: the widest vectors, the baseline ones,
/// the scalar reference), gives at every pixel of a noisy image the sum this test computes from
/// the mask's weights, for every mask and both signs: the SSE2, AVX2 and NEON kernels are
/// checked to the last bit against the plain sum.
#include <cstdint>
#include <string>
#include <vector>

#include "real/vector_kernels.h"
#include "testlib/testlib_test.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/mask_response.h"

namespace {

/// Pseudo-random grey levels, with whole rows of 0 and 255 (the extreme products).
vpImage<unsigned char> noisy_image(unsigned int height, unsigned int width) {
  vpImage<unsigned char> image(height, width);
  uint32_t state = 12345u;
  for (unsigned int i = 0; i < height; ++i)
    for (unsigned int j = 0; j < width; ++j) {
      state = state * 1664525u + 1013904223u;
      image[i][j] = i % 11 == 3 ? 255 : i % 13 == 5 ? 0 : static_cast<unsigned char>(state >> 24);
    }
  return image;
}

/// sign * sum of weight * pixel over the window centred at (i, j), 0 where the window reaches
/// upstream's border strip.
int expected_response(const vpImage<unsigned char>& image, const vpMe& me, unsigned int index, int sign, int i, int j) {
  const int size = static_cast<int>(me.getMaskSize()), half = (size - 1) / 2;
  const int margin = half + me.getStrip();
  if (i < margin + 1 || j < margin + 1 || i > static_cast<int>(image.getHeight()) - margin - 3 ||
      j > static_cast<int>(image.getWidth()) - margin - 3)
    return 0;
  const int16_t* weights = me.maskWeights(index);
  int total = 0;
  for (int a = 0; a < size; ++a)
    for (int b = 0; b < size; ++b) total += weights[a * size + b] * image[i - half + a][j - half + b];
  return sign * total;
}

#if defined(__SSE2__)
/// With the AVX2 kernels chosen and run: straight paths through every pixel in several directions
/// and of several lengths, read by path_each_5_avx2. Counts the pixels that differ from a scalar
/// walk's (each the product, then the sum, in double, truncated), the paths whose verdict (both
/// ends' windows inside) is wrong, and the responses of the paths inside that differ from
/// expected_response.
int wrong_path_responses(const vpImage<unsigned char>& image, const vpMe& me, const MaskResponse& response,
                         unsigned int index, int sign) {
  if (!response.runs_avx2()) return 0;
  const int height = static_cast<int>(image.getHeight()), width = static_cast<int>(image.getWidth());
  const int margin = static_cast<int>(me.getMaskSize() / 2) + me.getStrip();
  const auto inside = [&](int i, int j) {
    return i >= margin + 1 && j >= margin + 1 && i <= height - margin - 3 && j <= width - margin - 3;
  };
  const double directions[][2] = {{1, 0}, {0, 1}, {0.6, 0.8}, {-0.8, 0.6}, {0.7071067811865476, -0.7071067811865475},
                                  {-0.28, -0.96}};
  const int lengths[] = {5, 15, 16};
  int wrong = 0;
  for (int i = 0; i < height; ++i)
    for (int j = 0; j < width; ++j)
      for (const auto& direction : directions)
        for (int n : lengths) {
          const double y = i + 0.37, x = j + 0.61, dy = direction[0], dx = direction[1];
          const int k0 = -(n / 2);
          int rows[20], columns[20], out[20];
          const bool read = response.path_each_5_avx2(y, x, dy, dx, k0, n, rows, columns, out);
          for (int t = 0; t < n; ++t) {
            wrong += rows[t] != static_cast<int>(y + double(k0 + t) * dy);
            wrong += columns[t] != static_cast<int>(x + double(k0 + t) * dx);
          }
          wrong += read != (inside(rows[0], columns[0]) && inside(rows[n - 1], columns[n - 1]));
          if (read)
            for (int t = 0; t < n; ++t) wrong += out[t] != expected_response(image, me, index, sign, rows[t], columns[t]);
        }
  return wrong;
}
#endif

/// The number of responses, read every way at every pixel with the chosen kernels, that differ
/// from expected_response.
int wrong_responses(const vpImage<unsigned char>& image, const vpMe& me, unsigned int index, int sign) {
  const MaskResponse response(image, me, index, sign);
  const int height = static_cast<int>(image.getHeight()), width = static_cast<int>(image.getWidth());
  int wrong = 0;
  std::vector<int> rows, columns, out;
  for (int i = 0; i < height; ++i) {
    // A whole image row: at_each tests each pixel against the border, at_each_in_box its inner part.
    rows.assign(width, i);
    columns.resize(width);
    for (int j = 0; j < width; ++j) columns[j] = j;
    out.assign(width, -1);
    response.at_each(rows.data(), columns.data(), width, out.data());
    for (int j = 0; j < width; ++j) {
      const int expected = expected_response(image, me, index, sign, i, j);
      wrong += response.at(i, j) != expected;
      wrong += out[j] != expected;
    }
    // A diagonal run from (i, first inner column) to the bottom or right border strip, the pixels
    // a slanted path visits: inside from the first inner row on (runs of every length), else
    // starting outside.
    const int first = static_cast<int>(me.getMaskSize() / 2) + me.getStrip() + 1;
    const int last_i = height - first - 2, last_j = width - first - 2;
    const int length = last_i - i < last_j - first ? last_i - i + 1 : last_j - first + 1;
    if (length <= 0) continue;
    rows.resize(length);
    columns.resize(length);
    for (int k = 0; k < length; ++k) rows[k] = i + k, columns[k] = first + k;
    out.assign(length, -1);
    response.at_each_in_box(rows.data(), columns.data(), length, out.data());
    for (int k = 0; k < length; ++k) wrong += out[k] != expected_response(image, me, index, sign, rows[k], columns[k]);
  }
  for (int i = 1; i + 1 < height; ++i)
    for (int j = 1; j + 1 < width; ++j) {
      int block[9];
      response.at_block_3x3(i, j, expected_response(image, me, index, sign, i, j), block);
      for (int k = 0; k < 9; ++k) wrong += block[k] != expected_response(image, me, index, sign, i + k / 3 - 1, j + k % 3 - 1);
    }
#if defined(__SSE2__)
  wrong += wrong_path_responses(image, me, response, index, sign);
#endif
  return wrong;
}

/// Every `step`-th mask of size `size`, both signs, with each choice of kernels.
void check_masks(unsigned int size, unsigned int step) {
  vpMe me;
  me.setMaskSize(size);
  // 29 columns: the padded rows' reach (8 pixels from the window's left) ends at the last column.
  const vpImage<unsigned char> image = noisy_image(23, 29);
  const vector_kernels::Choice choices[] = {vector_kernels::Choice::kWidest, vector_kernels::Choice::kBaseline,
                                            vector_kernels::Choice::kScalar};
  const char* const names[] = {"widest", "baseline", "scalar"};
  for (int c = 0; c < 3; ++c) {
    vector_kernels::choose(choices[c]);
    int wrong = 0;
    for (unsigned int index = 0; index < me.getMaskNumber(); index += step)
      for (int sign = -1; sign <= 1; sign += 2) wrong += wrong_responses(image, me, index, sign);
    const std::string name = "mask size " + std::to_string(size) + ", " + names[c] + " kernels: wrong responses";
    TEST(name.c_str(), wrong, 0);
  }
  vector_kernels::choose(vector_kernels::Choice::kWidest);
}

}  // namespace

static void test_me_response() {
  check_masks(5, 1);  // upstream's default: the padded vector rows
  check_masks(3, 9);
  check_masks(7, 9);
}

TESTMAIN(test_me_response)
