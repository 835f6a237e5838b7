// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/algo/vnl_bracket_minimum.h"

#include <cmath>
#include <utility>

inline namespace edgetrack_ports {

namespace {
constexpr double kGolden = 1.618033988749895;  // the step growth between trials
constexpr double kMaxJump = 100.0;             // parabolic steps go at most this many steps further
constexpr double kTiny = 1e-20;

double value_at(vnl_cost_function& f, double x) {
  vnl_vector<double> v(1, x);
  return f.f(v);
}
}  // namespace

void vnl_bracket_minimum(vnl_cost_function& f, double& a, double& b, double& c, double& fa, double& fb,
                         double& fc) {
  fa = value_at(f, a);
  fb = value_at(f, b);
  if (fb > fa) {  // walk from a towards b downhill
    std::swap(a, b);
    std::swap(fa, fb);
  }
  c = b + kGolden * (b - a);
  fc = value_at(f, c);
  while (fc < fb) {
    // The vertex of the parabola through (a, fa), (b, fb), (c, fc).
    const double r = (b - a) * (fb - fc), q = (b - c) * (fb - fa);
    const double denominator = 2 * std::copysign(std::fmax(std::fabs(q - r), kTiny), q - r);
    double u = b - ((b - c) * q - (b - a) * r) / denominator;
    const double limit = b + kMaxJump * (c - b);
    double fu;
    if ((b - u) * (u - c) > 0) {  // between b and c
      fu = value_at(f, u);
      if (fu < fc) {
        a = b, fa = fb, b = u, fb = fu;
        return;
      }
      if (fu > fb) {
        c = u, fc = fu;
        return;
      }
      u = c + kGolden * (c - b);
      fu = value_at(f, u);
    } else if ((c - u) * (u - limit) > 0) {  // beyond c, within the limit
      fu = value_at(f, u);
      if (fu < fc) {
        b = c, c = u, u = c + kGolden * (c - b);
        fb = fc, fc = fu, fu = value_at(f, u);
      }
    } else {  // a golden step
      u = c + kGolden * (c - b);
      fu = value_at(f, u);
    }
    a = b, b = c, c = u;
    fa = fb, fb = fc, fc = fu;
  }
}

}  // inline namespace edgetrack_ports
