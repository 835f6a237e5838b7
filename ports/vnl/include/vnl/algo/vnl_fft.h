// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/algo/vnl_fft.h: the low-level interface upstream wraps around
/// Temperton's GPFA, for lengths N = 2^p 3^q 5^r. vnl_fft_setgpfa fills `triggs` (2 N values:
/// cos and sin of 2 pi k / N; our layout, not Temperton's) and pqr, and sets info to 0, or -1
/// when N has another prime factor. vnl_fft_gpfa transforms `lot` sequences in place, element
/// j of sequence l at a[l jump + j inc] (real parts) and b[...] (imaginary parts):
///   X(j) = sum_k C(k) exp(isign 2 pi i j k / N), unnormalised, isign = +1 forward, -1 backward.
#pragma once

#ifdef vnl_fft_h_
#error "edgetrack's drop-in vnl/algo/vnl_fft.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

void vnl_fft_setgpfa(float* triggs, long size, long pqr[3], long* info);
void vnl_fft_setgpfa(double* triggs, long size, long pqr[3], long* info);
void vnl_fft_gpfa(float* a, float* b, const float* triggs, long inc, long jump, long n, long lot, long isign,
                  const long pqr[3], long* info);
void vnl_fft_gpfa(double* a, double* b, const double* triggs, long inc, long jump, long n, long lot, long isign,
                  const long pqr[3], long* info);

}  // inline namespace edgetrack_ports
