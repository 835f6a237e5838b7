// SPDX-License-Identifier: BSD-3-Clause
/// vpMeTracker: the site list's initial search and frame-to-frame tracking.
#include "visp3/me/vpMeTracker.h"

#include <algorithm>

#include "visp3/core/vpMath.h"

inline namespace edgetrack_ports {

bool vpMeTracker::inMask(const vpImage<bool>* mask, unsigned int i, unsigned int j) {
  if (mask == nullptr) return true;
  if (i >= mask->getHeight() || j >= mask->getWidth()) return false;
  return (*mask)[i][j];
}

void vpMeTracker::init() { selectDisplay = vpMeSite::NONE; }

void vpMeTracker::reset() {
  nGoodElement = 0;
  list.clear();
}

unsigned int vpMeTracker::numberOfSignal() const {
  return static_cast<unsigned int>(std::count_if(list.begin(), list.end(), [](const vpMeSite& s) {
    return s.getState() == vpMeSite::NO_SUPPRESSION;
  }));
}

int vpMeTracker::outOfImage(int i, int j, int half, int rows, int cols) const {
  return !(i > half + 2 && i < rows - (half + 2) && j > half + 2 && j < cols - (half + 2));
}

int vpMeTracker::outOfImage(const vpImagePoint& iP, int half, int rows, int cols) const {
  return outOfImage(vpMath::round(iP.get_i()), vpMath::round(iP.get_j()), half, rows, cols);
}

void vpMeTracker::initTracking(const vpImage<unsigned char>& I) {
  nGoodElement = 0;
  if (me == nullptr) return;
  for (vpMeSite& s : list) {
    if (s.getState() != vpMeSite::NO_SUPPRESSION) continue;
    s.track(I, me, false, init_range);
    if (s.getState() == vpMeSite::NO_SUPPRESSION) ++nGoodElement;
  }
}

void vpMeTracker::track(const vpImage<unsigned char>& I) {
  nGoodElement = 0;
  if (me == nullptr) return;
  for (auto it = list.begin(); it != list.end();) {
    if (it->getState() != vpMeSite::NO_SUPPRESSION) {
      ++it;
      continue;
    }
    vpMeSite s = *it;
    s.track(I, me, true);
    if (!inMask(m_mask, static_cast<unsigned int>(s.i), static_cast<unsigned int>(s.j))) {
      it = list.erase(it);
      continue;
    }
    if (s.getState() != vpMeSite::THRESHOLD) ++nGoodElement;
    *it = s;
    ++it;
  }
}

}  // inline namespace edgetrack_ports
