// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_random.h: Marsaglia and Zaman's subtract-with-borrow generator
/// ("A New Class of Random Number Generators", Ann. Appl. Probab. 1991) with lags 37 and 24 on
/// 32-bit words, seeded and drawn exactly as upstream, so a seed gives upstream's numbers on
/// every platform. Two choices of ours: the default constructor and reseed() use the fixed seed
/// 9667566 where upstream reads the clock (runs are reproducible), and seed words are taken
/// modulo 2^32 (upstream's behaviour wherever unsigned long has 32 bits, as on ARM).
#pragma once

#ifdef vnl_random_h
#error "edgetrack's drop-in vnl/vnl_random.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <array>
#include <cstdint>

inline namespace edgetrack_ports {

/// The generator's lag: the number of 32-bit words in its state and in an array seed.
constexpr unsigned int vnl_random_array_size = 37;

class vnl_random {
 public:
  /// Seeded with 9667566 (upstream seeds from the clock).
  vnl_random();
  /// The 37 state words come from a linear congruential sequence started at `seed`, then 1000
  /// draws are discarded, as upstream.
  vnl_random(unsigned long seed);
  /// The state words are `seed` itself, with no draws discarded.
  vnl_random(const std::array<unsigned long, vnl_random_array_size>& seed);
  vnl_random(const unsigned long seed[vnl_random_array_size]);

  /// As the constructors. As upstream, a normal deviate pending from normal() or normal64()
  /// survives a reseed (and a restart).
  void reseed();
  void reseed(unsigned long seed);
  void reseed(const std::array<unsigned long, vnl_random_array_size>& seed);
  void reseed(const unsigned long seed[vnl_random_array_size]);
  /// As upstream: the state words return to the seed's (for a scalar seed, those before the 1000
  /// discarded draws) and the draw position to the first; the borrow stays as it is.
  void restart();

  /// A uniform 32-bit value: the next word of the subtract-with-borrow sequence.
  std::uint32_t next_uint32();
  /// A uniform integer in [a, b] (both included, a <= b): one word divided by
  /// floor((2^32 - 1) / (b - a + 1)), words that would bias the result drawn again.
  std::int32_t next_int32(std::int32_t a, std::int32_t b);
  std::int32_t next_int32(std::int32_t b) { return next_int32(0, b); }
  /// Upstream's older names for the same numbers.
  unsigned long lrand32() { return next_uint32(); }
  int lrand32(int a, int b) { return next_int32(a, b); }
  int lrand32(int b) { return next_int32(0, b); }
  /// As lrand32(a, b); `draws` receives how many words it took.
  int lrand32(int a, int b, int& draws);

  /// Uniform in [a, b] (both included) from one word: a + (b - a) * word / (2^32 - 1).
  double drand32(double a, double b);
  double drand32(double b) { return drand32(0.0, b); }
  double drand32() { return drand32(0.0, 1.0); }
  /// Uniform in [a, b] from two words, the first the high part. As upstream, the high word
  /// 2^32 - 1 with a nonzero low word gives b + (b - a) * 2^-32 at most.
  double drand64(double a, double b);
  double drand64(double b) { return drand64(0.0, b); }
  double drand64() { return drand64(0.0, 1.0); }
  /// Standard normal deviates (mean 0, variance 1) by Marsaglia's polar method, from drand32 and
  /// from drand64 pairs; each pair gives two deviates, the second kept for the next call of either.
  double normal();
  double normal64();

  /// An index in [0, n), so a vnl_random can drive std::shuffle-style algorithms.
  unsigned long operator()(unsigned n) { return static_cast<unsigned long>(next_int32(static_cast<std::int32_t>(n) - 1)); }

 private:
  double polar_normal(double (vnl_random::*uniform)(double, double));

  std::array<std::uint32_t, vnl_random_array_size> seed_words_{};
  std::array<std::uint32_t, vnl_random_array_size> words_{};
  unsigned position_ = 0;
  std::uint32_t borrow_ = 0;
  double pending_normal_ = 0;
  bool has_pending_normal_ = false;
};

}  // inline namespace edgetrack_ports
