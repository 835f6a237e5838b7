// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_na.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <string>

inline namespace edgetrack_ports {

namespace {
constexpr std::uint64_t kNaBits = 0x7FF00000000007A2ULL;   // R's NA: a NaN with payload 1954
constexpr std::uint32_t kNaBitsF = 0x7F8007A2U;           // the same payload in a float

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
std::uint32_t bits(float x) {
  std::uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

template <class T>
void extract(std::istream& is, T& x) {
  is >> std::ws;
  if (is.peek() == 'N') {
    // "NA" is two characters, not a word: "NA1.0" is NA then 1.0, as upstream reads it.
    is.get();
    if (is.peek() == 'A') {
      is.get();
      x = vnl_na(T());
      return;
    }
    is.setstate(std::ios::failbit);
    return;
  }
  is >> x;
}
}  // namespace

double vnl_na(double) {
  double x;
  std::memcpy(&x, &kNaBits, sizeof x);
  return x;
}

float vnl_na(float) {
  float x;
  std::memcpy(&x, &kNaBitsF, sizeof x);
  return x;
}

// Only the low 32 bits hold the payload; quiet and signalling NAs both count.
bool vnl_na_isna(double x) { return std::isnan(x) && (bits(x) & 0xFFFFFFFFULL) == (kNaBits & 0xFFFFFFFFULL); }
bool vnl_na_isna(float x) { return std::isnan(x) && (bits(x) & 0x3FFFFFU) == (kNaBitsF & 0x3FFFFFU); }

double vnl_na_nan_to_na(double v) { return std::isnan(v) ? vnl_na(double()) : v; }
float vnl_na_nan_to_na(float v) { return std::isnan(v) ? vnl_na(float()) : v; }

void vnl_na_extract(std::istream& is, double& x) { extract(is, x); }
void vnl_na_extract(std::istream& is, float& x) { extract(is, x); }

void vnl_na_insert(std::ostream& os, double x) {
  if (vnl_na_isna(x)) {
    os << "NA";
  } else {
    os << x;
  }
}

void vnl_na_insert(std::ostream& os, float x) {
  if (vnl_na_isna(x)) {
    os << "NA";
  } else {
    os << x;
  }
}

}  // inline namespace edgetrack_ports
