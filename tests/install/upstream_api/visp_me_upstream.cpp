// SPDX-License-Identifier: BSD-3-Clause
/// ViSP-style moving-edge settings and images, as a program for upstream ViSP writes them.
#include <cstdio>

#include <visp3/core/vpImage.h>
#include <visp3/me/vpMe.h>

int main() {
  vpMe me;
  me.setRange(7);
  me.setThreshold(5000.0);
  me.setMaskSize(5);
  me.setMaskNumber(180);
  vpImage<unsigned char> I(48, 64, 128);
  I[10][20] = 255;
  std::printf("range %u masks %u image %ux%u pixel %d\n", me.getRange(), me.getMaskNumber(), I.getWidth(),
              I.getHeight(), int(I[10][20]));
  return me.getRange() == 7 && me.getMaskNumber() == 180 && I.getWidth() == 64 && I[10][20] == 255 ? 0 : 1;
}
