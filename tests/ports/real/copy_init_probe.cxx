// SPDX-License-Identifier: BSD-3-Clause
// Compiled by copy_init_probe.sh, not built: with PROBE_DOUBLE it copy-initialises fixed64 from
// a double, which must not compile (a plain int constructor took 0.5 as 0); without it, the
// forms that must compile.
#include "real/fixed64.h"

using S40_23 = fixedpoint::fixed64<23>;

S40_23 stated_conversion() { return S40_23(0.5); }
S40_23 from_int() {
  S40_23 two = 2;
  return two * 3;
}
#ifdef PROBE_DOUBLE
S40_23 copy_initialised() {
  S40_23 half = 0.5;
  return half;
}
#endif
