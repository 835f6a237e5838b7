// SPDX-License-Identifier: BSD-3-Clause
/// What ViSP's example/tracking/trackMeLine.cpp does, without display or clicks, written against
/// ViSP's API only: it builds unchanged against ports/visp (host and ARM) and against Debian's
/// ViSP (tests/host/visp compares the two outputs). Set-up as upstream's example without clicks:
/// ViSP-images/line, vpMe range 15, 160 points to track, threshold 15000, the line through
/// (96, 191) and (122, 211) on frame 1; frame 1 tracked once more, then frames 1 to 29.
///
///   track_me_line [--sites]     prints per frame "line FRAME RHO THETA A B C SITES" and, with
///                               --sites, "site FRAME K STATE I J ALPHA" for every site in the list.
/// Exit 0 when every frame was tracked, 1 when the tracker threw.
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/me/vpMe.h>
#include <visp3/me/vpMeLine.h>
#include <visp3/me/vpMeSite.h>

#include <cstdio>
#include <list>
#include <string>

#include "example_io.h"

namespace {

void print_line(unsigned int frame, vpMeLine& line, bool sites) {
  double a, b, c;
  a = static_cast<double>(line.getA());
  b = static_cast<double>(line.getB());
  c = static_cast<double>(line.getC());
  const std::list<vpMeSite>& list = line.getMeList();
  std::printf("line %u %.9f %.9f %.9f %.9f %.9f %u\n", frame, static_cast<double>(line.getRho()),
              static_cast<double>(line.getTheta()), a, b, c, static_cast<unsigned int>(list.size()));
  if (sites) example::print_sites(frame, list);
}

}  // namespace

int main(int argc, char** argv) {
  const bool sites = example::wants_sites(argc, argv);
  const std::string dir = example::visp_images_path() + "/line";
  vpImage<unsigned char> I;
  if (!example::read_pgm(example::frame_path(dir, 1), I)) return 2;

  vpMe me;
  me.setRange(15);
  me.setPointsToTrack(160);
  me.setThreshold(15000);
  vpMeLine line;
  line.setMe(&me);
  line.setDisplay(vpMeSite::RANGE_RESULT);
  try {
    vpImagePoint ip1, ip2;
    ip1.set_i(96);
    ip1.set_j(191);
    ip2.set_i(122);
    ip2.set_j(211);
    line.initTracking(I, ip1, ip2);
    line.track(I);
    print_line(0, line, sites);
    for (unsigned int frame = 1; frame < 30; ++frame) {
      if (!example::read_pgm(example::frame_path(dir, frame), I)) return 2;
      line.track(I);
      print_line(frame, line, sites);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "track_me_line: tracking failed: %s\n", e.what());
    return 1;
  }
  return 0;
}
