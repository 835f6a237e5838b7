// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_random.h: a seedable pseudo-random generator of integers,
/// uniform doubles and normal deviates, with upstream's names. Our generator differs from
/// upstream's (a Marsaglia subtract-with-borrow): it is xoshiro128** (32-bit integer steps,
/// cheap on ARMv5) seeded by splitmix64, so sequences are reproducible per seed but are not
/// upstream's numbers. Normal deviates use the Marsaglia polar method, as upstream does.
#pragma once

#ifdef vnl_random_h
#error "edgetrack's drop-in vnl/vnl_random.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <array>
#include <cstdint>

inline namespace edgetrack_ports {

constexpr unsigned int vnl_random_array_size = 4;

class vnl_random {
 public:
  /// Seeded with upstream's default seed, 9667566.
  vnl_random();
  explicit vnl_random(unsigned long seed);
  explicit vnl_random(const std::array<unsigned long, vnl_random_array_size>& seed);

  /// Reseeds from the clock-free default sequence (the default seed).
  void reseed();
  void reseed(unsigned long seed);
  void reseed(const std::array<unsigned long, vnl_random_array_size>& seed);
  /// Starts the current seed's sequence again.
  void restart();

  /// A uniform 32-bit value.
  std::uint32_t next_uint32();
  /// A uniform integer in [a, b] (both included).
  std::int32_t next_int32(std::int32_t a, std::int32_t b);
  std::int32_t next_int32(std::int32_t b) { return next_int32(0, b); }
  /// Upstream's older names for the same.
  unsigned long lrand32() { return next_uint32(); }
  int lrand32(int a, int b) { return next_int32(a, b); }
  int lrand32(int b) { return next_int32(0, b); }

  /// Uniform in [a, b) from 32 random bits.
  double drand32(double a, double b);
  double drand32(double b) { return drand32(0.0, b); }
  double drand32() { return drand32(0.0, 1.0); }
  /// Uniform in [a, b) from 53 random bits.
  double drand64(double a, double b);
  double drand64(double b) { return drand64(0.0, b); }
  double drand64() { return drand64(0.0, 1.0); }
  /// Standard normal deviates (mean 0, variance 1), from drand32 and from drand64.
  double normal();
  double normal64();

  /// An index in [0, n), so a vnl_random can drive std::shuffle-style algorithms.
  unsigned long operator()(unsigned n) { return static_cast<unsigned long>(next_int32(static_cast<std::int32_t>(n) - 1)); }

 private:
  double polar_normal(double (vnl_random::*uniform)(double, double));

  std::array<std::uint32_t, 4> seed_state_{};
  std::array<std::uint32_t, 4> state_{};
  double previous_normal_ = 0;
  bool has_previous_normal_ = false;
};

}  // inline namespace edgetrack_ports
