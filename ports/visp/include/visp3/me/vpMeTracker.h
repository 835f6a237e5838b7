// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/me/vpMeTracker.h: a list of moving-edge sites tracked together, the base
/// of vpMeLine and vpMeEllipse. Upstream's vpTracker base (feature vectors p, cP) is not ported.
///
/// Differences from upstream (docs/ME.md): initTracking() searches with init_range through
/// vpMeSite::track(..., range) instead of changing the shared vpMe's range and restoring it, so
/// the vpMe is only read (setMe still takes a pointer, as upstream); no display code.
#pragma once

#ifdef vpMeTracker_HH
#error "edgetrack's drop-in visp3/me/vpMeTracker.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <list>

#include "visp3/core/vpImage.h"
#include "visp3/core/vpImagePoint.h"
#include "visp3/me/vpMe.h"
#include "visp3/me/vpMeSite.h"

inline namespace edgetrack_ports {

class vpMeTracker {
 public:
  vpMeTracker() = default;
  vpMeTracker(const vpMeTracker&) = default;
  vpMeTracker& operator=(const vpMeTracker&) = default;
  virtual ~vpMeTracker() = default;

  /// Test whether pixel (i, j) takes part in the tracking: no mask, or the mask is true there
  /// (false outside the mask image).
  static bool inMask(const vpImage<bool>* mask, unsigned int i, unsigned int j);

  unsigned int getInitRange() const { return init_range; }
  vpMe* getMe() { return me; }
  std::list<vpMeSite>& getMeList() { return list; }
  std::list<vpMeSite> getMeList() const { return list; }
  /// Sites kept by the last track() (upstream's nGoodElement).
  int getNbPoints() const { return nGoodElement; }

  void init();
  /// Snaps each kept site onto the strongest edge within +-init_range (no contrast test).
  void initTracking(const vpImage<unsigned char>& I);
  /// Sites in the NO_SUPPRESSION state.
  unsigned int numberOfSignal() const;
  unsigned int totalNumberOfSignal() const { return static_cast<unsigned int>(list.size()); }
  /// True when (i, j) is within half + 2 pixels of the border (upstream's rule).
  int outOfImage(int i, int j, int half, int rows, int cols) const;
  int outOfImage(const vpImagePoint& iP, int half, int rows, int cols) const;
  void reset();
  virtual void sample(const vpImage<unsigned char>& image, bool doNotTrack = false) = 0;
  void setDisplay(vpMeSite::vpMeSiteDisplayType select) { selectDisplay = select; }
  void setInitRange(const unsigned int& r) { init_range = r; }
  virtual void setMask(const vpImage<bool>& mask) { m_mask = &mask; }
  void setMe(vpMe* p_me) { me = p_me; }
  void setMeList(const std::list<vpMeSite>& l) { list = l; }
  /// Tracks each kept site with the contrast test; sites outside the mask are removed.
  void track(const vpImage<unsigned char>& I);

 protected:
  std::list<vpMeSite> list;
  vpMe* me = nullptr;
  unsigned int init_range = 1;
  int nGoodElement = 0;
  const vpImage<bool>* m_mask = nullptr;
  vpMeSite::vpMeSiteDisplayType selectDisplay = vpMeSite::NONE;
};

}  // inline namespace edgetrack_ports
