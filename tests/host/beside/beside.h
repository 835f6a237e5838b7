// SPDX-License-Identifier: BSD-3-Clause
/// The two halves of one program: one translation unit uses our drop-in visp_me port, the other
/// Debian's real ViSP (visp_core and visp_io). Only plain types cross between them.
#pragma once

#include <string>

/// Our vpMeSite tracks a vertical step edge at column `edge_column` of a 48 x 48 vpImage from a
/// start 3 pixels to its left; returns the column it stops on (-1 if it lost the edge).
int ours_track_vertical_step(int edge_column);

/// Real ViSP writes a `rows` x `cols` ramp vpImage<unsigned char> (pixel (i, j) = i + 2 j) to
/// `pgm_path` with vpImageIo and reads it back; returns the sum of the read pixels, or -1 if the
/// size read back differs.
long upstream_pgm_round_trip(const std::string& pgm_path, unsigned rows, unsigned cols);
