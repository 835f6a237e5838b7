// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_random.h"

#include <cmath>

inline namespace edgetrack_ports {

namespace {
constexpr unsigned long kDefaultSeed = 9667566;

std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint32_t rotl(std::uint32_t x, int k) { return (x << k) | (x >> (32 - k)); }
}  // namespace

vnl_random::vnl_random() { reseed(kDefaultSeed); }
vnl_random::vnl_random(unsigned long seed) { reseed(seed); }
vnl_random::vnl_random(const std::array<unsigned long, vnl_random_array_size>& seed) { reseed(seed); }

void vnl_random::reseed() { reseed(kDefaultSeed); }

void vnl_random::reseed(unsigned long seed) {
  std::uint64_t x = seed;
  const std::uint64_t a = splitmix64(x), b = splitmix64(x);
  seed_state_ = {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(a >> 32), static_cast<std::uint32_t>(b),
                 static_cast<std::uint32_t>(b >> 32)};
  restart();
}

void vnl_random::reseed(const std::array<unsigned long, vnl_random_array_size>& seed) {
  std::uint64_t x = 0;
  for (unsigned i = 0; i < vnl_random_array_size; ++i) {
    x ^= seed[i];
    seed_state_[i] = static_cast<std::uint32_t>(splitmix64(x));
  }
  restart();
}

void vnl_random::restart() {
  state_ = seed_state_;
  if ((state_[0] | state_[1] | state_[2] | state_[3]) == 0) state_[0] = 1;  // xoshiro's one bad state
  has_previous_normal_ = false;
}

std::uint32_t vnl_random::next_uint32() {
  const std::uint32_t result = rotl(state_[1] * 5, 7) * 9;
  const std::uint32_t t = state_[1] << 9;
  state_[2] ^= state_[0];
  state_[3] ^= state_[1];
  state_[1] ^= state_[2];
  state_[0] ^= state_[3];
  state_[2] ^= t;
  state_[3] = rotl(state_[3], 11);
  return result;
}

std::int32_t vnl_random::next_int32(std::int32_t a, std::int32_t b) {
  // Rejection sampling: exactly uniform over the b - a + 1 values.
  const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(b) - a) + 1;
  const std::uint64_t limit = (std::uint64_t{1} << 32) - ((std::uint64_t{1} << 32) % span);
  std::uint64_t x;
  do {
    x = next_uint32();
  } while (x >= limit);
  return static_cast<std::int32_t>(a + static_cast<std::int64_t>(x % span));
}

double vnl_random::drand32(double a, double b) { return a + (b - a) * (next_uint32() * (1.0 / 4294967296.0)); }

double vnl_random::drand64(double a, double b) {
  const std::uint64_t bits = (static_cast<std::uint64_t>(next_uint32()) << 21) ^ (next_uint32() >> 11);
  return a + (b - a) * (static_cast<double>(bits & ((std::uint64_t{1} << 53) - 1)) * (1.0 / 9007199254740992.0));
}

double vnl_random::polar_normal(double (vnl_random::*uniform)(double, double)) {
  if (has_previous_normal_) {
    has_previous_normal_ = false;
    return previous_normal_;
  }
  double x, y, r2;
  do {
    x = (this->*uniform)(-1.0, 1.0);
    y = (this->*uniform)(-1.0, 1.0);
    r2 = x * x + y * y;
  } while (r2 >= 1.0 || r2 == 0.0);
  const double scale = std::sqrt(-2.0 * std::log(r2) / r2);
  previous_normal_ = y * scale;
  has_previous_normal_ = true;
  return x * scale;
}

double vnl_random::normal() { return polar_normal(&vnl_random::drand32); }
double vnl_random::normal64() { return polar_normal(&vnl_random::drand64); }

}  // inline namespace edgetrack_ports
