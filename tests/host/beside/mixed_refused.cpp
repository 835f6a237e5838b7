// SPDX-License-Identifier: BSD-3-Clause
/// Must not compile: Debian's vpImage.h, then our drop-in of the same header in one translation
/// unit (by its path, since both answer to <visp3/core/vpImage.h>). The test expects our
/// header's #error naming the clash.
#include <visp3/core/vpImage.h>

#include "../../../ports/visp/include/visp3/core/vpImage.h"
