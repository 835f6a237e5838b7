// SPDX-License-Identifier: BSD-3-Clause
// vnl_sample as upstream's test_sample.cxx: the sample mean and spread of the uniform, normal,
// binomial and Bernoulli samplers (one by one and through the range fillers) match the
// distributions', and reseeding with a seed repeats the samples. Upstream draws 100000 samples
// after a clock seed; we draw 20000 (quick under QEMU; upstream's tolerances are then 2.8
// standard errors for the normal mean, more for the others) after fixed seeds, so the
// outcome is the same on every run (vnl_drand48 is exact integer arithmetic).
#include <cmath>
#include <vector>

#include "testlib/testlib_test.h"
#include "vnl/vnl_sample.h"

namespace {
constexpr unsigned kN = 20000;
constexpr double kEps = 0.02;  // upstream's tolerance factor

template <class V>
double mean_of(const std::vector<V>& x) {
  double sum = 0;
  for (const V v : x) sum += v;
  return sum / x.size();
}
template <class V>
double variance_of(const std::vector<V>& x) {
  const double m = mean_of(x);
  double sum = 0;
  for (const V v : x) sum += (v - m) * (v - m);
  return sum / (x.size() - 1);
}

void test_sample_uniform() {
  const double a = 123.456, b = 543.210;
  vnl_sample_reseed(1);
  std::vector<double> x(kN);
  for (double& v : x) v = vnl_sample_uniform(a, b);
  TEST_NEAR("uniform: sample mean", mean_of(x), (a + b) / 2, kEps * a);
  TEST_NEAR("uniform: sample stddev", std::sqrt(variance_of(x)), (b - a) / std::sqrt(12.0), kEps * a);
  bool in_range = true;
  for (const double v : x) in_range = in_range && v >= a && v < b;
  TEST("uniform: every sample in [a, b)", in_range, true);

  vnl_sample_reseed(977);
  const double u0 = vnl_sample_uniform(0.0, 1.0);
  vnl_sample_reseed(977);
  TEST("uniform: reseeding repeats the sample", vnl_sample_uniform01(), u0);

  vnl_sample_uniform(x.begin(), x.end(), a, b);
  TEST_NEAR("uniform range filler: sample mean", mean_of(x), (a + b) / 2, kEps * a);
  TEST_NEAR("uniform range filler: sample stddev", std::sqrt(variance_of(x)), (b - a) / std::sqrt(12.0), kEps * a);
  std::vector<float> xf(kN);
  vnl_sample_uniform(xf.begin(), xf.end(), a, b, 0.0f);
  TEST_NEAR("uniform range filler to float: sample mean", mean_of(xf), (a + b) / 2, kEps * a);
}

void test_sample_normal() {
  const double mu = 1.552, sigma = 3.729;
  vnl_sample_reseed(2);
  std::vector<double> x(kN);
  for (double& v : x) v = vnl_sample_normal(mu, sigma);
  TEST_NEAR("normal: sample mean", mean_of(x), mu, kEps * sigma);
  TEST_NEAR("normal: sample stddev", std::sqrt(variance_of(x)), sigma, kEps * sigma);

  vnl_sample_reseed(4242);
  const double n0 = vnl_sample_normal(0.0, 1.0);
  vnl_sample_reseed(4242);
  TEST("normal: reseeding repeats the sample", vnl_sample_normal(0.0, 1.0), n0);

  vnl_sample_normal(x.begin(), x.end(), mu, sigma);
  TEST_NEAR("normal range filler: sample mean", mean_of(x), mu, kEps * sigma);
  TEST_NEAR("normal range filler: sample stddev", std::sqrt(variance_of(x)), sigma, kEps * sigma);

  double y0 = 0, y1 = 0;
  vnl_sample_normal_2(&y0, &y1);
  TEST("normal_2 gives two finite samples", std::isfinite(y0) && std::isfinite(y1), true);
}

void test_sample_binomial() {
  const int n = 10;
  const double p = 0.4;
  vnl_sample_reseed(3);
  std::vector<int> x(kN);
  for (int& v : x) v = vnl_sample_binomial(n, p);
  // As upstream, each of the n draws is 1 with probability 1 - p.
  TEST_NEAR("binomial: sample mean", mean_of(x), n * (1 - p), kEps * n);
  TEST_NEAR("binomial: sample variance", variance_of(x), p * (1 - p) * n, kEps * n);
  vnl_sample_binomial(x.begin(), x.end(), n, p);
  TEST_NEAR("binomial range filler: sample mean", mean_of(x), n * (1 - p), kEps * n);
  TEST_NEAR("binomial range filler: sample variance", variance_of(x), p * (1 - p) * n, kEps * n);
  TEST("binomial: nonsense input gives -1", vnl_sample_binomial(0, p) == -1 && vnl_sample_binomial(n, 1.5) == -1, true);
  TEST("binomial: q = 1 gives n", vnl_sample_binomial(n, 1.0), n);
}

void test_sample_bernoulli() {
  const double p = 0.7;
  vnl_sample_reseed(4);
  std::vector<int> x(kN);
  for (int& v : x) v = vnl_sample_bernoulli(p);
  TEST_NEAR("Bernoulli: sample mean", mean_of(x), 1 - p, kEps);
  TEST_NEAR("Bernoulli: sample variance", variance_of(x), p * (1 - p), kEps);
  vnl_sample_bernoulli(x.begin(), x.end(), p);
  TEST_NEAR("Bernoulli range filler: sample mean", mean_of(x), 1 - p, kEps);
  TEST_NEAR("Bernoulli range filler: sample variance", variance_of(x), p * (1 - p), kEps);
  TEST("Bernoulli: q outside [0, 1] gives -1", vnl_sample_bernoulli(-0.1), -1);
  TEST("Bernoulli: q = 0 gives 0, q = 1 gives 1", vnl_sample_bernoulli(0.0) == 0 && vnl_sample_bernoulli(1.0) == 1,
       true);
}
}  // namespace

static void test_sample() {
  vnl_sample_reseed();  // from the clock, as upstream starts; the checks below reseed
  test_sample_normal();
  test_sample_uniform();
  test_sample_binomial();
  test_sample_bernoulli();
}

TESTMAIN(test_sample)
