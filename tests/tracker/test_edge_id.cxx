// SPDX-License-Identifier: BSD-3-Clause
/// The Edge-ID code: equations (4)-(12) name every edge up to 32767 exactly, also after the
/// colour has been through a 16-bit RGB565 buffer; the naive byte code does not survive RGB565.
#include "edgetrack/edge_id.h"
#include "edgetrack/edge_model.h"
#include "testlib/testlib_test.h"

using namespace edgetrack;

static void test_edge_id() {
  TEST("edge 0 is coded (0, 0, 8): equation (4)", (encode_edge_id(0) == Rgb888{0, 0, 8}), true);
  TEST("edge 31 is coded (0, 8, 0): the blue code wraps into green", (encode_edge_id(31) == Rgb888{0, 8, 0}), true);
  TEST("edge 1023 is coded (8, 0, 0): green wraps into red", (encode_edge_id(1023) == Rgb888{8, 0, 0}), true);
  TEST("edge 32766 is coded (248, 248, 248), the last code", (encode_edge_id(32766) == Rgb888{248, 248, 248}), true);
  TEST_EQUAL("black decodes to -1, the background", decode_edge_id(Rgb888()), -1);

  int direct_errors = 0, rgb565_errors = 0, channel_not_multiple_of_8 = 0;
  for (int i = 0; i < kMaxEdges; ++i) {
    const Rgb888 c = encode_edge_id(i);
    direct_errors += decode_edge_id(c) != i;
    rgb565_errors += decode_edge_id(unpack_rgb565(pack_rgb565(c))) != i;
    channel_not_multiple_of_8 += (c.r % 8) != 0 || (c.g % 8) != 0 || (c.b % 8) != 0;
  }
  TEST_EQUAL("equations (10)-(12) invert (4)-(9) for all 32767 edges", direct_errors, 0);
  TEST_EQUAL("all 32767 codes survive an RGB565 buffer", rgb565_errors, 0);
  TEST_EQUAL("every channel is a multiple of 8, the paper's spacing", channel_not_multiple_of_8, 0);
  int bitwise_errors = 0;
  for (int value = 0; value < 65536; ++value) {
    const uint16_t pixel = static_cast<uint16_t>(value);
    bitwise_errors += decode_edge_id_rgb565(pixel) != decode_edge_id(unpack_rgb565(pixel));
  }
  TEST_EQUAL("the bitwise decoding agrees with equations (10)-(12) on every RGB565 pixel", bitwise_errors, 0);

  // The naive code (index + 1 in three bytes) loses the low 3 bits of blue in RGB565: edges
  // 0..6 read back as background or as another edge, and pairs of edges become the same colour.
  int naive_direct_errors = 0, naive_565_errors = 0, naive_collisions = 0;
  const int naive_count = 4096;
  for (int i = 0; i < naive_count; ++i) {
    naive_direct_errors += decode_edge_id_naive(encode_edge_id_naive(i)) != i;
    naive_565_errors += decode_edge_id_naive(unpack_rgb565(pack_rgb565(encode_edge_id_naive(i)))) != i;
    naive_collisions += i > 0 && pack_rgb565(encode_edge_id_naive(i)) == pack_rgb565(encode_edge_id_naive(i - 1));
  }
  TEST_EQUAL("the naive code is exact in a 24-bit buffer", naive_direct_errors, 0);
  TEST("the naive code misreads most edges through RGB565", naive_565_errors > naive_count / 2, true);
  TEST("through RGB565 the naive code gives neighbouring edges the same colour", naive_collisions > 0, true);
  TEST_EQUAL("through RGB565 the naive code reads edge 0 as the background",
             decode_edge_id_naive(unpack_rgb565(pack_rgb565(encode_edge_id_naive(0)))), -1);
  TEST("the 8-level codes of neighbouring edges differ in RGB565",
       pack_rgb565(encode_edge_id(0)) != pack_rgb565(encode_edge_id(1)), true);
}

TESTMAIN(test_edge_id)
