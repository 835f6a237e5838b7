// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors ViSP's visp3/me/vpMe.h: the moving-edge parameters, with upstream's names, meanings
/// and defaults, and the oriented convolution masks built from them.
///
/// Differences from upstream (docs/ME.md says why): scalars are `real`; masks are int16_t
/// tables in one contiguous block instead of n_mask vpMatrix objects (every upstream weight is
/// already round(100 * sign * area), an integer); the mask index is clamped to the table.
#pragma once

#ifdef vpMe_H
#error "edgetrack's drop-in visp3/me/vpMe.h and ViSP's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <cstdint>
#include <string>
#include <vector>

#include "real/real.h"

inline namespace edgetrack_ports {

/// One mask_size x mask_size mask: `mask[a][b]` is the weight of row a, column b.
class vpMeMask {
 public:
  vpMeMask(const int16_t* weights, unsigned int size) : weights_(weights), size_(size) {}
  const int16_t* operator[](unsigned int row) const { return weights_ + row * size_; }
  const int16_t* data() const { return weights_; }

 private:
  const int16_t* weights_;
  unsigned int size_;
};

/// The table of masks: `getMask()[k][a][b]` reads as upstream's vpMatrix array does.
class vpMeMaskTable {
 public:
  vpMeMaskTable(const int16_t* weights, unsigned int size) : weights_(weights), size_(size) {}
  vpMeMask operator[](unsigned int k) const { return vpMeMask(weights_ + k * size_ * size_, size_); }

 private:
  const int16_t* weights_;
  unsigned int size_;
};

class vpMe {
 public:
  /// Upstream's defaults: threshold 1500, mu1 = mu2 = 0.5, min_samplestep 4, range 4,
  /// sample_step 10, mask_size 5, n_mask 180 (anglestep 1 degree), strip 2.
  vpMe();

  void checkSamplestep(real& a) const {
    if (a < min_samplestep) a = min_samplestep;
  }

  unsigned int getAngleStep() const { return anglestep; }
  vpMeMaskTable getMask() const { return vpMeMaskTable(masks_.data(), mask_size); }
  unsigned int getMaskNumber() const { return n_mask; }
  int getMaskSign() const { return mask_sign; }
  unsigned int getMaskSize() const { return mask_size; }
  real getMinSampleStep() const { return min_samplestep; }
  real getMu1() const { return mu1; }
  real getMu2() const { return mu2; }
  int getNbTotalSample() const { return ntotal_sample; }
  int getPointsToTrack() const { return points_to_track; }
  unsigned int getRange() const { return range; }
  real getSampleStep() const { return sample_step; }
  int getStrip() const { return strip; }
  real getThreshold() const { return threshold; }

  /// Prints the settings to stdout in upstream's words and layout.
  void print();
  /// New: the text print() writes.
  std::string settingsText() const;

  /// Rebuilds the masks from mask_size and n_mask (upstream calls it from the setters too).
  void initMask();

  void setAngleStep(const unsigned int& a) { anglestep = a; }
  /// n_mask orientations, anglestep = 180 / n_mask degrees apart (at least 1); rebuilds the masks.
  void setMaskNumber(const unsigned int& n);
  void setMaskSign(const int& a) { mask_sign = a; }
  /// Masks of s x s pixels; rebuilds the masks.
  void setMaskSize(const unsigned int& s);
  void setMinSampleStep(const real& m) { min_samplestep = m; }
  void setMu1(const real& m) { mu1 = m; }
  void setMu2(const real& m) { mu2 = m; }
  void setNbTotalSample(const int& nb) { ntotal_sample = nb; }
  void setPointsToTrack(const int& n) { points_to_track = n; }
  void setRange(const unsigned int& r) { range = r; }
  void setSampleStep(const real& s) { sample_step = s; }
  void setStrip(const int& a) { strip = a; }
  void setThreshold(const real& t) { threshold = t; }
#if defined(EDGETRACK_REAL_S47_16) || defined(EDGETRACK_REAL_S40_23)
  // Fixed-point `real` converts from double only explicitly; these keep code written against
  // upstream (which passes double constants) compiling. Set-up only: one conversion per call.
  void setMinSampleStep(const double& m) { min_samplestep = real(m); }
  void setMu1(const double& m) { mu1 = real(m); }
  void setMu2(const double& m) { mu2 = real(m); }
  void setSampleStep(const double& s) { sample_step = real(s); }
  void setThreshold(const double& t) { threshold = real(t); }
#endif

  /// The mask for a normal angle alpha (radians): upstream's index, computed once per site.
  unsigned int maskIndex(const real& alpha) const;
  /// Weights of mask `index` (mask_size * mask_size, row-major).
  const int16_t* maskWeights(unsigned int index) const { return masks_.data() + index * mask_size * mask_size; }
  /// True when every mask is antisymmetric: the weight of row a, column b is minus that of row
  /// n-1-a, column n-1-b (so the centre's is 0). The area rule gives this by construction; it is
  /// checked on the rounded weights, and lets a response take one product per pixel pair.
  bool masksAntisymmetric() const { return masks_antisymmetric_; }
  /// Entries per row of paddedMaskWeights: 8 on SSE2 hosts and with NEON (AArch64, ARMv7-A with
  /// -mfpu=neon), where MaskResponse takes a row of 8 products in vector multiply-adds, 0 (no
  /// padded masks) elsewhere, as on ARMv5TE.
#if defined(__SSE2__) || defined(__ARM_NEON)
  static constexpr unsigned int kPaddedRow = 8;
#else
  static constexpr unsigned int kPaddedRow = 0;
#endif
  /// Weights of mask `index`, each row followed by zeros up to kPaddedRow entries; null when
  /// kPaddedRow is 0 or smaller than mask_size.
  const int16_t* paddedMaskWeights(unsigned int index) const {
    return padded_masks_.empty() ? nullptr : padded_masks_.data() + index * mask_size * kPaddedRow;
  }

 private:
  real threshold;
  real mu1;
  real mu2;
  real min_samplestep;
  unsigned int anglestep;
  int mask_sign;
  unsigned int range;
  real sample_step;
  int ntotal_sample;
  int points_to_track;
  unsigned int mask_size;
  unsigned int n_mask;
  int strip;
  std::vector<int16_t> masks_;
  bool masks_antisymmetric_ = false;
  std::vector<int16_t> padded_masks_;
};

}  // inline namespace edgetrack_ports
