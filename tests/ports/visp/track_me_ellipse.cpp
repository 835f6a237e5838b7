// SPDX-License-Identifier: BSD-3-Clause
/// What ViSP's example/tracking/trackMeEllipse.cpp does, without display or clicks, written
/// against ViSP's API only: it builds unchanged against ports/visp (host and ARM) and against
/// Debian's ViSP (tests/host/visp compares the two outputs). Set-up as upstream's example without
/// clicks: ViSP-images/ellipse-1, vpMe range 20, sample step 10 (degrees), threshold 15000, the
/// whole ellipse through (195, 329), (243, 164), (201, 36), (83, 126), (33, 276) on frame 1,
/// then frames 1 to 50.
///
///   track_me_ellipse [--sites]  prints per frame "ellipse FRAME UC VC A B E N20 N11 N02 SITES"
///                               and, with --sites, "site FRAME K STATE I J ALPHA" for every site.
/// Exit 0 when every frame was tracked, 1 when the tracker threw.
#include <visp3/core/vpColVector.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/me/vpMe.h>
#include <visp3/me/vpMeEllipse.h>
#include <visp3/me/vpMeSite.h>

#include <cstdio>
#include <list>
#include <string>
#include <vector>

#include "example_io.h"

namespace {

void print_ellipse(unsigned int frame, vpMeEllipse& ellipse, bool sites) {
  const vpImagePoint centre = ellipse.getCenter();
  const vpColVector abe = ellipse.get_ABE(), nij = ellipse.get_nij();
  const std::list<vpMeSite>& list = ellipse.getMeList();
  std::printf("ellipse %u %.9f %.9f %.9f %.9f %.9f %.9f %.9f %.9f %u\n", frame, static_cast<double>(centre.get_u()),
              static_cast<double>(centre.get_v()), static_cast<double>(abe[0]), static_cast<double>(abe[1]),
              static_cast<double>(abe[2]), static_cast<double>(nij[0]), static_cast<double>(nij[1]),
              static_cast<double>(nij[2]), static_cast<unsigned int>(list.size()));
  if (sites) example::print_sites(frame, list);
}

}  // namespace

int main(int argc, char** argv) {
  const bool sites = example::wants_sites(argc, argv);
  const std::string dir = example::visp_images_path() + "/ellipse-1";
  vpImage<unsigned char> I;
  if (!example::read_pgm(example::frame_path(dir, 1), I)) return 2;

  vpMe me;
  me.setRange(20);
  me.setSampleStep(10);
  me.setThreshold(15000);
  vpMeEllipse ellipse;
  ellipse.setMe(&me);
  ellipse.setDisplay(vpMeSite::RANGE_RESULT);
  try {
    std::vector<vpImagePoint> ip;
    ip.push_back(vpImagePoint(195, 329));
    ip.push_back(vpImagePoint(243, 164));
    ip.push_back(vpImagePoint(201, 36));
    ip.push_back(vpImagePoint(83, 126));
    ip.push_back(vpImagePoint(33, 276));
    ellipse.initTracking(I, ip, false);
    print_ellipse(0, ellipse, sites);
    for (unsigned int frame = 1; frame < 51; ++frame) {
      if (!example::read_pgm(example::frame_path(dir, frame), I)) return 2;
      ellipse.track(I);
      print_ellipse(frame, ellipse, sites);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "track_me_ellipse: tracking failed: %s\n", e.what());
    return 1;
  }
  return 0;
}
