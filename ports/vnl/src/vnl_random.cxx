// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_random.h"

#include <cassert>
#include <cmath>

inline namespace edgetrack_ports {

namespace {
constexpr unsigned long kDefaultSeed = 9667566;
// The word subtracted from is the one drawn 24 steps before the word it replaces (the short lag).
constexpr unsigned kShortLag = 24;
// Upstream's linear congruential step for a scalar seed, and the draws discarded after it.
constexpr std::uint32_t kSeedMultiplier = 1664525;
constexpr int kWarmUpDraws = 1000;
constexpr double kWordMax = 4294967295.0;  // 2^32 - 1, the divisor upstream's doubles use
}  // namespace

vnl_random::vnl_random() { reseed(kDefaultSeed); }
vnl_random::vnl_random(unsigned long seed) { reseed(seed); }
vnl_random::vnl_random(const std::array<unsigned long, vnl_random_array_size>& seed) { reseed(seed); }
vnl_random::vnl_random(const unsigned long seed[vnl_random_array_size]) { reseed(seed); }

void vnl_random::reseed() { reseed(kDefaultSeed); }

void vnl_random::reseed(unsigned long seed) {
  auto lcg = static_cast<std::uint32_t>(seed);
  for (std::uint32_t& word : seed_words_) word = lcg = lcg * kSeedMultiplier + 1;
  words_ = seed_words_;
  position_ = 0;
  borrow_ = 0;
  for (int i = 0; i < kWarmUpDraws; ++i) next_uint32();
}

void vnl_random::reseed(const std::array<unsigned long, vnl_random_array_size>& seed) { reseed(seed.data()); }

void vnl_random::reseed(const unsigned long seed[vnl_random_array_size]) {
  for (unsigned i = 0; i < vnl_random_array_size; ++i) seed_words_[i] = static_cast<std::uint32_t>(seed[i]);
  words_ = seed_words_;
  position_ = 0;
  borrow_ = 0;
}

void vnl_random::restart() {
  words_ = seed_words_;
  position_ = 0;
}

std::uint32_t vnl_random::next_uint32() {
  const std::uint32_t lagged = words_[(position_ + vnl_random_array_size - kShortLag) % vnl_random_array_size];
  const std::uint32_t word = lagged - words_[position_] - borrow_;
  // The borrow is what the subtraction took from beyond 32 bits; an equal result leaves it.
  if (word < lagged) borrow_ = 0;
  if (word > lagged) borrow_ = 1;
  words_[position_] = word;
  position_ = (position_ + 1) % vnl_random_array_size;
  return word;
}

std::int32_t vnl_random::next_int32(std::int32_t a, std::int32_t b) {
  int draws;
  return lrand32(a, b, draws);
}

int vnl_random::lrand32(int a, int b, int& draws) {
  assert(a <= b);
  const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(b) - a + 1);
  draws = 1;
  if (span > 0xffffffffu) return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + next_uint32());  // all of int32
  // Words at or above the largest multiple of `span` that fits would favour the low values.
  const auto step = static_cast<std::uint32_t>(0xffffffffu / span);
  const std::uint64_t limit = std::uint64_t{step} * span;
  std::uint32_t word;
  while ((word = next_uint32()) >= limit) ++draws;
  return a + static_cast<std::int32_t>(word / step);
}

double vnl_random::drand32(double a, double b) {
  assert(a <= b);
  return (next_uint32() / kWordMax) * (b - a) + a;
}

double vnl_random::drand64(double a, double b) {
  assert(a <= b);
  const double high = next_uint32() / kWordMax;
  const double low = next_uint32() / (kWordMax * kWordMax);
  return (high + low) * (b - a) + a;
}

double vnl_random::polar_normal(double (vnl_random::*uniform)(double, double)) {
  if (has_pending_normal_) {
    has_pending_normal_ = false;
    return pending_normal_;
  }
  double x, y, r2;
  do {
    x = (this->*uniform)(-1.0, 1.0);
    y = (this->*uniform)(-1.0, 1.0);
    r2 = x * x + y * y;
  } while (r2 >= 1.0 || r2 == 0.0);
  const double scale = std::sqrt(-2.0 * std::log(r2) / r2);
  pending_normal_ = x * scale;
  has_pending_normal_ = true;
  return y * scale;
}

double vnl_random::normal() { return polar_normal(&vnl_random::drand32); }
double vnl_random::normal64() { return polar_normal(&vnl_random::drand64); }

}  // inline namespace edgetrack_ports
