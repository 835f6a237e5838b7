// SPDX-License-Identifier: BSD-3-Clause
#include "vnl/vnl_sample.h"

#include <cmath>
#include <ctime>

#include "vnl/vnl_drand48.h"
#include "vnl/vnl_math.h"

inline namespace edgetrack_ports {

void vnl_sample_reseed() { vnl_srand48(static_cast<long>(std::time(nullptr))); }

void vnl_sample_reseed(int seed) { vnl_srand48(seed); }

double vnl_sample_uniform(double a, double b) {
  const double u = vnl_drand48();
  return (1.0 - u) * a + u * b;
}

double vnl_sample_uniform01() { return vnl_sample_uniform(0.0, 1.0); }

void vnl_sample_normal_2(double* x, double* y) {
  const double u = vnl_sample_uniform(1.0, 0.0);  // on (0, 1]: the logarithm stays finite
  const double theta = vnl_sample_uniform(0.0, vnl_math::twopi);
  const double r = std::sqrt(-2.0 * std::log(u));
  if (x) *x = r * std::cos(theta);
  if (y) *y = r * std::sin(theta);
}

double vnl_sample_normal(double mean, double sigma) {
  double x = 0.0;
  vnl_sample_normal_2(&x, nullptr);
  return mean + sigma * x;
}

int vnl_sample_bernoulli(double q) {
  if (q == 0.0) return 0;
  if (q == 1.0) return 1;
  if (q < 0.0 || q > 1.0) return -1;
  return vnl_sample_uniform01() >= q ? 1 : 0;
}

int vnl_sample_binomial(int n, double q) {
  if (n <= 0 || q < 0.0 || q > 1.0) return -1;
  if (q == 0.0) return 0;
  if (q == 1.0) return n;
  int k = 0;
  for (int i = 0; i < n; ++i) k += vnl_sample_bernoulli(q);
  return k;
}

}  // inline namespace edgetrack_ports
