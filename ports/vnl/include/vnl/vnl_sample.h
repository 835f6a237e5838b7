// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_sample.h: samples of uniform, normal, Bernoulli and binomial
/// distributions drawn from vnl_drand48's process-wide sequence, as upstream (so not
/// thread-safe; reseeding affects every caller). The range fillers write one sample per
/// element of [begin, end). User code on double; vnl_random serves one generator per owner.
#pragma once

#ifdef vnl_sample_h_
#error "edgetrack's drop-in vnl/vnl_sample.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

/// Seeds from the clock (different runs, different samples).
void vnl_sample_reseed();
void vnl_sample_reseed(int seed);

/// Uniform on [0, 1).
double vnl_sample_uniform01();
/// Uniform on [a, b) (on (b, a] when b < a).
double vnl_sample_uniform(double a, double b);
/// Two independent standard normal samples (Box-Muller); either pointer may be null.
void vnl_sample_normal_2(double* x, double* y);
/// Normal with the given mean and standard deviation.
double vnl_sample_normal(double mean, double sigma);
/// The number of ones among n Bernoulli samples of parameter q; -1 when n <= 0 or q is
/// outside [0, 1].
int vnl_sample_binomial(int n, double q);
/// As upstream: 0 with probability q and 1 with probability 1 - q for 0 < q < 1, but 0 for
/// q == 0 and 1 for q == 1; -1 when q is outside [0, 1].
int vnl_sample_bernoulli(double q);

template <class I>
inline void vnl_sample_uniform(I begin, I end, double a, double b) {
  for (I p = begin; p != end; ++p) *p = vnl_sample_uniform(a, b);
}
template <class I>
inline void vnl_sample_normal(I begin, I end, double mean, double sigma) {
  for (I p = begin; p != end; ++p) *p = vnl_sample_normal(mean, sigma);
}
template <class I>
inline void vnl_sample_binomial(I begin, I end, int n, double q) {
  for (I p = begin; p != end; ++p) *p = vnl_sample_binomial(n, q);
}
template <class I>
inline void vnl_sample_bernoulli(I begin, I end, double q) {
  for (I p = begin; p != end; ++p) *p = vnl_sample_bernoulli(q);
}
/// The same, converting each sample to T (the last argument only names the type).
template <class I, class T>
inline void vnl_sample_uniform(I begin, I end, double a, double b, T /*type*/) {
  for (I p = begin; p != end; ++p) *p = T(vnl_sample_uniform(a, b));
}
template <class I, class T>
inline void vnl_sample_normal(I begin, I end, double mean, double sigma, T /*type*/) {
  for (I p = begin; p != end; ++p) *p = T(vnl_sample_normal(mean, sigma));
}

}  // inline namespace edgetrack_ports
