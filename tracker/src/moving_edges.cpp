// SPDX-License-Identifier: BSD-3-Clause
/// The moving-edge search per control point, vpMeSite's search on the ported masks, with a
/// sub-pixel refinement that varies continuously with the control point.
#include "edgetrack/moving_edges.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "edgetrack/normal_mask.h"
#include "real/vector_kernels.h"
#include "visp3/me/mask_response.h"

namespace edgetrack {

namespace {

/// Pixels a ridge search may climb from its start to reach the likelihood's local maximum; it
/// then reads one more for the parabola (kRefinementReachAlong in the header).
constexpr int kMaxClimb = kRefinementReachAlong - 1;

/// Reads |mask response| with the site's orientation in "axis" coordinates: u along the image
/// axis nearest to the normal, v along the other one. 0 near the border.
class AxisLikelihood {
 public:
  AxisLikelihood(const MaskResponse& response, bool along_x) : response_(response), along_x_(along_x) {}
  int at(int u, int v) const {
    const int value = along_x_ ? response_.at(v, u) : response_.at(u, v);
    return value < 0 ? -value : value;
  }

 private:
  const MaskResponse& response_;
  bool along_x_;
};

/// The edge's position on line v: from u, whose likelihood and its neighbours' are `centre`,
/// `before` (u - 1) and `after` (u + 1), climbs (at most kMaxClimb pixels, ties towards lower
/// u, the same in every build) to a local maximum of the likelihood, then fits a parabola
/// through it and its two neighbours. `peak` receives the maximum's likelihood.
real ridge_on_line(const AxisLikelihood& likelihood, int u, int v, int before, int centre, int after, int& peak) {
  for (int climb = 0; climb < kMaxClimb && (before > centre || after > centre); ++climb) {
    if (before >= after) {
      --u;
      after = centre;
      centre = before;
      before = likelihood.at(u - 1, v);
    } else {
      ++u;
      before = centre;
      centre = after;
      after = likelihood.at(u + 1, v);
    }
  }
  peak = centre;
  const int curvature = before - 2 * centre + after;
  if (curvature < 0 && centre >= before && centre >= after)
    return real(u) + real(before - after) / (2 * curvature);  // within half a pixel of u
  return real(u);
}

/// The sub-pixel edge point near the site's pixel (i, j), of the site's mask `response`, whose
/// value there the search read already (`conv`).
/// The site keeps a whole pixel of its path, and which pixel that is (which row, for a mostly
/// vertical edge) flips with a rounding-size move of the control point. So the edge is located
/// on the three lines of the axis nearest to the normal around that pixel (a ridge each), and
/// the match is where the control point's normal line crosses the polyline through those
/// ridges: a continuous function of the control point.
Vec2 refined_edge_point(const MaskResponse& response, int i, int j, int conv, const ControlPoint& point) {
  using std::fabs;
  const bool along_x = fabs(point.normal.x) >= fabs(point.normal.y);
  const int u_site = along_x ? j : i, v_site = along_x ? i : j;
  const AxisLikelihood likelihood(response, along_x);
  const real u0 = along_x ? point.pixel.x : point.pixel.y, v0 = along_x ? point.pixel.y : point.pixel.x;
  const real nu = along_x ? point.normal.x : point.normal.y, nv = along_x ? point.normal.y : point.normal.x;
  static_assert(kRefinementReachAcross == 1, "three lines: the site's and one either side");
  // The 3 x 3 pixels around the site's in one batch (image rows, then columns; the centre is
  // the site's own response, conv), in axis order: block[3 (v - v_site + 1) + u - u_site + 1].
  int image_block[9], block[9];
  response.at_block_3x3(i, j, conv, image_block);
  for (int k = 0; k < 9; ++k) block[k] = along_x ? image_block[k] : image_block[3 * (k % 3) + k / 3];
  real ridge[3], side[3];  // side: (edge point - control point) . edge direction, 0 on the normal line
  int peak[3];
  for (int k = 0; k < 3; ++k) {
    const int* line = block + 3 * k;
    ridge[k] = ridge_on_line(likelihood, u_site, v_site + k - 1, line[0] < 0 ? -line[0] : line[0],
                             line[1] < 0 ? -line[1] : line[1], line[2] < 0 ? -line[2] : line[2], peak[k]);
    side[k] = nu * (real(v_site + k - 1) - v0) - nv * (ridge[k] - u0);
  }
  real u = ridge[1], v = real(v_site);
  // Both neighbours must show the same edge (at least half the peak) for the polyline.
  if (2 * peak[0] >= peak[1] && 2 * peak[2] >= peak[1]) {
    // side grows with v along a straight edge (d side / dv = 1 / nu): take the segment on
    // the side of the middle line where side changes sign. Where it does not (lines that
    // show different edges), the crossing is clamped to the segment's ends, which keeps the
    // match next to the site's pixel and still continuous.
    const int k = (side[1] > real(0)) == (nu > real(0)) ? 0 : 1;
    const real span = side[k] - side[k + 1];
    if (span != real(0)) {
      real t = side[k] / span;
      if (t < real(0)) t = real(0);
      if (t > real(1)) t = real(1);
      u = ridge[k] + t * (ridge[k + 1] - ridge[k]);
      v = real(v_site + k - 1) + t;
    }
  }
  return along_x ? Vec2{u, v} : Vec2{v, u};
}

/// A local maximum of the likelihood on a site's search path, at a whole pixel. Not initialised:
/// a search fills the ones it counts.
struct PathPeak {
  int likelihood;
  int i;
  int j;
  int conv;
};

/// The pixel a site's search keeps, with its signed mask response (EdgeMatch::contrast).
struct SitePixel {
  int i = 0;
  int j = 0;
  int conv = 0;
};

/// The pixels of a site's path in order, k = -range..range: pixel + k normal, truncated. The
/// fixed-point builds step by the normal, which adds up to exactly pixel + k normal; floating
/// point multiplies, as its steps would add rounding.
class PathWalk {
 public:
  PathWalk(const ControlPoint& point, int range)
      : point_(point), k_(-range), y_(point.pixel.y - range * point.normal.y), x_(point.pixel.x - range * point.normal.x) {}
  void next(int& i, int& j) {
    if (std::is_floating_point<real>::value) {
      i = static_cast<int>(point_.pixel.y + k_ * point_.normal.y);
      j = static_cast<int>(point_.pixel.x + k_ * point_.normal.x);
      ++k_;
    } else {
      i = static_cast<int>(y_);
      j = static_cast<int>(x_);
      y_ += point_.normal.y;
      x_ += point_.normal.x;
    }
  }

 private:
  const ControlPoint& point_;
  int k_;
  real y_, x_;
};

/// The integers n with real(n) > threshold: those with n > likelihood_floor(threshold).
int likelihood_floor(const real& threshold) {
  using std::floor;
  constexpr int kLimit = 1 << 30;  // far beyond any likelihood
  if (threshold > real(kLimit)) return kLimit;
  if (threshold < real(-kLimit)) return -kLimit;
  return static_cast<int>(floor(threshold));
}

/// What every site's search takes from vpMe, converted once per frame.
struct SiteLimits {
  SiteLimits(const vpMe& me, unsigned int search_range)
      : range(static_cast<int>(search_range)),
        threshold(likelihood_floor(me.getThreshold())),
        least(real(1) - me.getMu1()),
        most(real(1) + me.getMu2()),
        vector(vector_kernels::chosen() != vector_kernels::Choice::kScalar),
        avx2(vector_kernels::avx2()) {}
  int range;      ///< candidates pixel + k normal, |k| <= range
  int threshold;  ///< maxima of likelihood above it
  real least, most;  ///< the contrast test's bounds, times |reference|
  bool vector;       ///< the vector kernels, else the scalar reference (vector_kernels.h)
  bool avx2;         ///< the vector kernels built for AVX2
};

#if defined(__SSE2__)
/// PathWalk's pixels k0 .. k0 + n - 1 of the path (k0 = -range first) into i[] and j[], two at a
/// time: each lane the scalar walk's product and sum, truncated alike. Writes i[n] and j[n] when n
/// is odd.
void path_pixels_in_pairs(double y, double x, double dy, double dx, int k0, int n, int* i, int* j) {
  const __m128d start_y = _mm_set1_pd(y), start_x = _mm_set1_pd(x);
  const __m128d step_y = _mm_set1_pd(dy), step_x = _mm_set1_pd(dx);
  const __m128d two = _mm_set1_pd(2.0);
  __m128d k = _mm_set_pd(double(k0 + 1), double(k0));  // small integers: exact steps of 2
  for (int t = 0; t < n; t += 2, k = _mm_add_pd(k, two)) {
    _mm_storel_epi64(reinterpret_cast<__m128i*>(i + t), _mm_cvttpd_epi32(_mm_add_pd(start_y, _mm_mul_pd(k, step_y))));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(j + t), _mm_cvttpd_epi32(_mm_add_pd(start_x, _mm_mul_pd(k, step_x))));
  }
}

/// A chunk of a site's path in double builds, the walk's pixels (i[], j[], rounded up to a
/// multiple of 4) and their responses (conv[], likewise) computed in vectors: in one AVX2 pass
/// where the mask runs it, else the pixels two at a time and the responses in one batch. True.
[[maybe_unused]] bool path_chunk_in_vectors(const MaskResponse& response, const double& y, const double& x,
                                            const double& dy, const double& dx, int k0, int n, int* i, int* j, int* conv) {
  if (response.runs_avx2()) {
    if (!response.path_each_5_avx2(y, x, dy, dx, k0, n, i, j, conv)) response.at_each(i, j, n, conv);
    return true;
  }
  path_pixels_in_pairs(y, x, dy, dx, k0, n, i, j);
  response.at_each_in_box(i, j, n, conv);
  return true;
}

/// The other reals: false, the caller steps (PathWalk).
template <class Real>
bool path_chunk_in_vectors(const MaskResponse&, const Real&, const Real&, const Real&, const Real&, int, int, int*, int*,
                           int*) {
  return false;
}

/// path_peaks_in_chunks' slots: slot kLead + k holds a chunk's k-th pixel, slots 0 and 1 the
/// previous chunk's last two (likelihood -1 before the path); the tests reach a vector past the
/// chunk.
constexpr int kChunk = 16, kLead = 2, kSlots = kLead + kChunk + 8;
static_assert(kChunk + 2 <= 32, "one bit per candidate slot");
static_assert(kChunk <= MaskResponse::kMaxPathEach && kLead + kChunk + 8 <= kSlots, "a chunk in one path_each_5_avx2, 8 slots past it");

/// The candidates of a chunk whose n responses are in conv[kLead..]: the pixels whose neighbour
/// after them the chunk read (slots 1..n; none before the path, so from `first`), and at the
/// path's far end its last pixel, with no pixel after it (last: n + 1, else n).
struct ChunkCandidates {
  int n, first, last;
  bool far_end;
};

/// Fills likelihood[kLead..] with |2 conv| and returns the chunk's local maxima of the likelihood
/// above `threshold`, bit t for slot t: at > before, at >= after, branch-free four at a time.
/// conv's slots past the n-th (to a multiple of 4) are set to 0.
unsigned chunk_peaks_sse2(int* likelihood, int* conv, const ChunkCandidates& c, int threshold) {
  for (int k = c.n; k % 4 != 0; ++k) conv[kLead + k] = 0;
  for (int k = 0; k < c.n; k += 4) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(conv + kLead + k));
    const __m128i sign = _mm_srai_epi32(v, 31);
    const __m128i magnitude = _mm_sub_epi32(_mm_xor_si128(v, sign), sign);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(likelihood + kLead + k), _mm_add_epi32(magnitude, magnitude));
  }
  if (c.far_end) likelihood[kLead + c.n] = -1;
  const __m128i floor_of_peaks = _mm_set1_epi32(threshold);
  unsigned candidates = 0;
  for (int t = 1; t <= c.last; t += 4) {
    const __m128i at = _mm_loadu_si128(reinterpret_cast<const __m128i*>(likelihood + t));
    const __m128i before = _mm_loadu_si128(reinterpret_cast<const __m128i*>(likelihood + t - 1));
    const __m128i after = _mm_loadu_si128(reinterpret_cast<const __m128i*>(likelihood + t + 1));
    // at > before, at >= after (not after > at), and at above the threshold.
    const __m128i peak = _mm_andnot_si128(_mm_cmpgt_epi32(after, at),
                                          _mm_and_si128(_mm_cmpgt_epi32(at, before), _mm_cmpgt_epi32(at, floor_of_peaks)));
    candidates |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(peak))) << t;
  }
  return candidates & ((2u << c.last) - 1) & ~((1u << c.first) - 1);
}

#if defined(__x86_64__) && defined(EDGETRACK_VECTOR_KERNELS_TWICE)
/// chunk_peaks_sse2 eight at a time; the far end's slot kChunk + 1, past the two vectors, alone.
/// conv's 8 slots past the n-th are set to 0. Inlined into the search's AVX2 build
/// (search_sites_avx2).
[[gnu::target("avx2")]] inline unsigned chunk_peaks_avx2(int* likelihood, int* conv, const ChunkCandidates& c,
                                                         int threshold) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(conv + kLead + c.n), _mm256_setzero_si256());
  for (int k = 0; k < c.n; k += 8) {
    const __m256i magnitude = _mm256_abs_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(conv + kLead + k)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(likelihood + kLead + k), _mm256_add_epi32(magnitude, magnitude));
  }
  if (c.far_end) likelihood[kLead + c.n] = -1;
  const __m256i floor_of_peaks = _mm256_set1_epi32(threshold);
  unsigned candidates = 0;
  for (int t = 1; t <= c.last && t <= kChunk; t += 8) {
    const __m256i at = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(likelihood + t));
    const __m256i before = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(likelihood + t - 1));
    const __m256i after = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(likelihood + t + 1));
    const __m256i peak = _mm256_andnot_si256(
        _mm256_cmpgt_epi32(after, at), _mm256_and_si256(_mm256_cmpgt_epi32(at, before), _mm256_cmpgt_epi32(at, floor_of_peaks)));
    candidates |= static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(peak))) << t;
  }
  if (c.last > kChunk) {
    const int* at = likelihood + kChunk + 1;
    candidates |= static_cast<unsigned>(at[0] > at[-1] && at[0] >= at[1] && at[0] > threshold) << (kChunk + 1);
  }
  return candidates & ((2u << c.last) - 1) & ~((1u << c.first) - 1);
}
#endif

/// for_each_path_peak's vector path: the responses a chunk of the path at a time (MaskResponse
/// loads the mask once per chunk), and the maxima of each chunk tested four pixels at a time
/// (AVX2: eight), branch-free.
template <class Visit>
void path_peaks_in_chunks(const MaskResponse& response, const SiteLimits& limits, const ControlPoint& point, Visit visit) {
  const int range = limits.range, threshold = limits.threshold;
  PathWalk walk(point, range);
  const int length = 2 * range + 1;
  int likelihood[kSlots], conv[kSlots], path_i[kSlots], path_j[kSlots];
  for (int t = 0; t < kSlots; ++t) likelihood[t] = -1;
  for (int start = 0; start < length; start += kChunk) {
    const int n = length - start < kChunk ? length - start : kChunk;
    if (!path_chunk_in_vectors(response, point.pixel.y, point.pixel.x, point.normal.y, point.normal.x, start - range, n,
                               path_i + kLead, path_j + kLead, conv + kLead)) {
      for (int k = 0; k < n; ++k) walk.next(path_i[kLead + k], path_j[kLead + k]);
      response.at_each_in_box(path_i + kLead, path_j + kLead, n, conv + kLead);
    }
    const bool far_end = start + n == length;
    const ChunkCandidates chunk{n, start == 0 ? kLead : 1, far_end ? n + 1 : n, far_end};
#if defined(__x86_64__) && defined(EDGETRACK_VECTOR_KERNELS_TWICE)
    unsigned candidates = limits.avx2 ? chunk_peaks_avx2(likelihood, conv, chunk, threshold)
                                      : chunk_peaks_sse2(likelihood, conv, chunk, threshold);
#else
    unsigned candidates = chunk_peaks_sse2(likelihood, conv, chunk, threshold);
#endif
    for (; candidates != 0; candidates &= candidates - 1) {
      const int t = __builtin_ctz(candidates);
      visit(conv[t], path_i[t], path_j[t]);
    }
    if (far_end) break;
    for (int t = 0; t < kLead; ++t) {
      likelihood[t] = likelihood[n + t];
      conv[t] = conv[n + t];
      path_i[t] = path_i[n + t];
      path_j[t] = path_j[n + t];
    }
  }
}
#endif

/// for_each_path_peak's scalar reference.
template <class Visit>
void path_peaks_one_by_one(const MaskResponse& response, const SiteLimits& limits, const ControlPoint& point, Visit visit) {
  const int range = limits.range, threshold = limits.threshold;
  PathWalk walk(point, range);
  const int length = 2 * range + 1;
  // One response at a time: arrays would cost more than they save. before, current: the
  // likelihoods of the pixels before the current one (i, j) and of it; each pixel read (`after`)
  // settles whether the current one is a maximum.
  int before = -1, current = -1, current_conv = 0, i = 0, j = 0;
  for (int k = 0; k < length; ++k) {
    int next_i = 0, next_j = 0;
    walk.next(next_i, next_j);
    const int conv = response.at(next_i, next_j);
    const int after = conv < 0 ? -2 * conv : 2 * conv;
    if (k > 0 && current > before && current >= after && current > threshold) visit(current_conv, i, j);
    before = k > 0 ? current : -1;
    current = after;
    current_conv = conv;
    i = next_i;
    j = next_j;
  }
  if (current > before && current > threshold) visit(current_conv, i, j);  // the far end: no pixel after
}

/// Calls visit(conv, i, j) at each local maximum, in path order, of the likelihood |2 conv| above
/// the threshold on the site's search path: the 2 range + 1 candidates pixel + k normal,
/// |k| <= range, truncated to whole pixels, as vpMeSite::track visits them but with the unit
/// normal in place of (cos alpha, sin alpha), which saves a sine and a cosine per point and
/// differs by rounding only. conv is the signed response of the site's mask; a path end counts as
/// a maximum when its one neighbour is lower, as the site's search keeps an end.
template <class Visit>
void for_each_path_peak(const MaskResponse& response, const SiteLimits& limits, const ControlPoint& point, Visit visit) {
#if defined(__SSE2__)
  if (limits.vector) {
    path_peaks_in_chunks(response, limits, point, visit);
    return;
  }
#endif
  path_peaks_one_by_one(response, limits, point, visit);
}

/// What one pass over a site's path (for_each_path_peak) finds for the site's search and its
/// alternatives, so that no choice reads the path's responses twice.
struct PathSearch {
  /// vpMeSite::track(I, &me, false): the maximum of the largest likelihood above the threshold,
  /// the first of equals; valid when strongest_magnitude > 0.
  SitePixel strongest;
  int strongest_magnitude = 0;
  /// Upstream's contrast test against the reference (with one): of the maxima whose conv has the
  /// reference's sign and lies within (1 - mu1, 1 + mu2) times it, the strongest. (Upstream takes
  /// the pixel whose contrast is nearest to the reference: where a face turns into view beside a
  /// silhouette, its far edge has the silhouette's old contrast, and on the generated frames that
  /// rule followed it off the cube.) Valid when contrast_magnitude > 0.
  SitePixel by_contrast;
  int contrast_magnitude = 0;
  /// The strongest maxima (at most the capacity asked for, strongest first, ties in path
  /// order), for the alternatives.
  PathPeak peaks[kMaxHypotheses + 1];
  int peak_count = 0;
};

/// One pass over the site's path. `reference` is the oriented contrast (EdgeMatch::contrast)
/// the same model point showed in the last trusted frame, 0 for none; `capacity` (at most
/// kMaxHypotheses + 1) is how many maxima to keep in `peaks`, 0 for none.
PathSearch search_path(const MaskResponse& response, const SiteLimits& limits, const ControlPoint& point,
                       const real& reference, int capacity) {
  using std::fabs;
  PathSearch found;
  const bool with_reference = reference != real(0);
  real least(0), most(0);
  if (with_reference) {
    least = limits.least * fabs(reference);
    most = limits.most * fabs(reference);
  }
  const bool positive = reference > real(0);
  for_each_path_peak(response, limits, point, [&](int conv, int i, int j) {
    const int magnitude = conv < 0 ? -conv : conv;
    if (magnitude > found.strongest_magnitude) {
      found.strongest_magnitude = magnitude;
      found.strongest = {i, j, conv};
    }
    if (with_reference && (conv > 0) == positive && real(magnitude) > least && real(magnitude) < most &&
        magnitude > found.contrast_magnitude) {
      found.contrast_magnitude = magnitude;
      found.by_contrast = {i, j, conv};
    }
    if (capacity > 0) {
      const int likelihood = 2 * magnitude;
      int at = found.peak_count < capacity ? found.peak_count++ : capacity;  // insertion into the sorted list
      while (at > 0 && found.peaks[at - 1].likelihood < likelihood) {
        if (at < capacity) found.peaks[at] = found.peaks[at - 1];
        --at;
      }
      if (at < capacity) found.peaks[at] = {likelihood, i, j, conv};
    }
  });
  return found;
}

/// The site's pixel: by the contrast test with a reference, else, or when no edge passes it (the
/// edge's look changed: a new background behind a silhouette, a shadow), the strongest edge
/// within the range, as the paper's tracker takes; a strict reference (borrowed from the
/// primitive for a point not seen last time) leaves the site unmatched instead. False when the
/// site is unmatched.
bool choose_site(const PathSearch& found, const real& reference, bool strict, SitePixel& site) {
  if (reference != real(0) && found.contrast_magnitude > 0) {
    site = found.by_contrast;
    return true;
  }
  if (reference != real(0) && strict) return false;
  site = found.strongest;
  return found.strongest_magnitude > 0;
}

/// Adds the weaker local maxima of the site's path (`found`, kept with capacity hypotheses + 1)
/// as alternatives of `match` (up to hypotheses - 1), each refined as the strongest is. Only
/// maxima of at least half the strongest likelihood compete (weaker ones are mostly noise and
/// background texture, which the pose step would otherwise fit), and a maximum whose refined
/// point lies within a pixel (along the normal) of one already kept is the same edge reached
/// again.
void add_alternatives(const MaskResponse& response, const PathSearch& found, int hypotheses, const SitePixel& site,
                      EdgeMatch& match) {
  using std::fabs;
  const PathPeak* peaks = found.peaks;
  for (int p = 0; p < found.peak_count && match.alternative_count < hypotheses - 1; ++p) {
    if (2 * peaks[p].likelihood < peaks[0].likelihood) break;  // too weak to compete
    if (peaks[p].i == site.i && peaks[p].j == site.j) continue;
    const Vec2 q = refined_edge_point(response, peaks[p].i, peaks[p].j, peaks[p].conv, match.point);
    bool known = fabs(dot(match.point.normal, q - match.found)) < real(1);
    for (int a = 0; a < match.alternative_count && !known; ++a)
      known = fabs(dot(match.point.normal, q - match.alternatives[a])) < real(1);
    if (!known) match.alternatives[match.alternative_count++] = q;
  }
}

}  // namespace

vpMe moving_edge_masks(const MovingEdgeParams& params) {
  vpMe me;
  me.setThreshold(params.threshold);
  me.setMu1(params.mu1);
  me.setMu2(params.mu2);
  me.setSampleStep(params.sample_step);
  me.setMaskSize(params.mask_size);
  me.setMaskNumber(params.mask_number);
  return me;
}

void contrasts_at_points(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         std::vector<real>& out) {
  out.assign(points.size(), real(0));
  for (size_t p = 0; p < points.size(); ++p) {
    const ControlPoint& point = points[p];
    const NormalMask mask = normal_mask(me, point.normal);
    const MaskResponse response(grey, me, mask.index, mask.sign);
    out[p] = real(response.at(static_cast<int>(point.pixel.y), static_cast<int>(point.pixel.x)));
  }
}

std::vector<EdgeMatch> search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points,
                                           const vpMe& me, unsigned int range, int hypotheses,
                                           const std::vector<real>* references,
                                           const std::vector<unsigned char>* strict) {
  std::vector<EdgeMatch> matches;
  search_moving_edges(grey, points, me, range, hypotheses, matches, references, strict);
  return matches;
}

namespace {

/// search_moving_edges with its limits.
void search_sites(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                  const SiteLimits& limits, int hypotheses, std::vector<EdgeMatch>& matches,
                  const std::vector<real>* references, const std::vector<unsigned char>* strict) {
  // The slots of the last frame's matches are written over, field by field, rather than built
  // anew: a new EdgeMatch would zero its alternatives, which only alternative_count of are read.
  size_t kept = 0;
  matches.reserve(points.size());
  // The points of one straight edge share its normal, so its mask is looked up once per run.
  Vec2 mask_normal{real(0), real(0)};
  std::optional<MaskResponse> mask_response;
  const size_t count = points.size();  // in a local: the stores to matches could alias the vector's size
  for (size_t p = 0; p < count; ++p) {
    const ControlPoint& point = points[p];
    if (p == 0 || !(point.normal.x == mask_normal.x && point.normal.y == mask_normal.y)) {
      const NormalMask mask = normal_mask(me, point.normal);
      mask_response.emplace(grey, me, mask.index, mask.sign);
      mask_normal = point.normal;
    }
    const MaskResponse& response = *mask_response;
    const real reference = references ? (*references)[p] : real(0);
    const PathSearch found = search_path(response, limits, point, reference, hypotheses > 1 ? hypotheses + 1 : 0);
    SitePixel site;
    if (!choose_site(found, reference, strict && (*strict)[p] != 0, site)) continue;
    if (kept == matches.size()) matches.emplace_back();
    EdgeMatch& match = matches[kept++];
    match.point = point;
    match.point_index = static_cast<int>(p);
    match.found = refined_edge_point(response, site.i, site.j, site.conv, point);
    match.outlier = false;
    match.excluded = false;
    match.contrast = real(site.conv);
    match.alternative_count = 0;
    match.chosen = 0;
    if (hypotheses > 1) add_alternatives(response, found, hypotheses, site, match);
  }
  matches.erase(matches.begin() + static_cast<std::ptrdiff_t>(kept), matches.end());
}

#if defined(__x86_64__) && defined(EDGETRACK_VECTOR_KERNELS_TWICE)
/// search_sites built for AVX2 with its callees in this file inlined, the chunks' peaks among
/// them: a call per site's path cost more than the peaks' test.
[[gnu::target("avx2"), gnu::flatten]] void search_sites_avx2(const vpImage<unsigned char>& grey,
                                                            const std::vector<ControlPoint>& points, const vpMe& me,
                                                            const SiteLimits& limits, int hypotheses,
                                                            std::vector<EdgeMatch>& matches,
                                                            const std::vector<real>* references,
                                                            const std::vector<unsigned char>* strict) {
  search_sites(grey, points, me, limits, hypotheses, matches, references, strict);
}
#endif

}  // namespace

void search_moving_edges(const vpImage<unsigned char>& grey, const std::vector<ControlPoint>& points, const vpMe& me,
                         unsigned int range, int hypotheses, std::vector<EdgeMatch>& matches, const std::vector<real>* references,
                         const std::vector<unsigned char>* strict) {
  const SiteLimits limits(me, range);
#if defined(__x86_64__) && defined(EDGETRACK_VECTOR_KERNELS_TWICE)
  if (limits.avx2) {
    search_sites_avx2(grey, points, me, limits, hypotheses, matches, references, strict);
    return;
  }
#endif
  search_sites(grey, points, me, limits, hypotheses, matches, references, strict);
}

}  // namespace edgetrack
