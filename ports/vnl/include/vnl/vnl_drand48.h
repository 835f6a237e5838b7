// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's core/vnl/vnl_drand48.h: POSIX drand48/srand48 on every platform, giving the
/// same numbers as the C library's for a seed. As upstream, the generator state is one
/// process-wide variable: not thread-safe, and every caller shares the sequence (use
/// vnl_random for a generator of one's own).
#pragma once

#ifdef __local_drand48_h__
#error "edgetrack's drop-in vnl/vnl_drand48.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

inline namespace edgetrack_ports {

/// The next number of the 48-bit linear congruential sequence, uniform on [0, 1).
double vnl_drand48();
/// Restarts the sequence: the state becomes (seed's low 32 bits << 16) | 0x330E.
void vnl_srand48(long seed);

}  // inline namespace edgetrack_ports
