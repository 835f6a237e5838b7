// SPDX-License-Identifier: BSD-3-Clause
/// The half that uses our drop-in visp_me (ports/visp): vpImage and vpMeSite as upstream spells them.
#include "beside.h"
#include "visp3/core/vpImage.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

int ours_track_vertical_step(int edge_column) {
  vpImage<unsigned char> I(48, 48, 40);
  for (unsigned i = 0; i < I.getHeight(); ++i)
    for (unsigned j = static_cast<unsigned>(edge_column); j < I.getWidth(); ++j) I[i][j] = 200;
  const vpMe me;
  vpMeSite site;
  site.init(24.0, edge_column - 3.0, 0.0);  // normal along +j
  site.track(I, &me, false);
  return site.getState() == vpMeSite::NO_SUPPRESSION ? site.get_j() : -1;
}
