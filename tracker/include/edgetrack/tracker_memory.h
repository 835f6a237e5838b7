// SPDX-License-Identifier: BSD-3-Clause
/// Where a tracker's heap goes, buffer by buffer: the RAM budget of a microcontroller
/// (docs/MCU.md) is read from this and checked against the allocator's own count.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace edgetrack {

/// The bytes a vector holds on the heap: its capacity, not its size.
template <class T>
size_t capacity_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

/// A tracker's heap per buffer, bytes reserved (Tracker::memory).
struct TrackerMemory {
  size_t model = 0;            ///< the tracker's copy of the EdgeModel
  size_t edge_id_image = 0;    ///< the Edge-ID image: half a byte per pixel up to 15 primitives, a byte up to 255, else RGB565
  size_t edge_id_lines = 0;    ///< per pixel of one line, the nearest surface's depth and owner; the lines and triangles
  size_t grey_image = 0;       ///< the grey image (none while the frames are grey8, read in place)
  size_t control_points = 0;   ///< the sampled points, then the visible ones; their read boxes and reference contrasts
  size_t matches = 0;          ///< the moving edges' matches
  size_t pose_workspace = 0;   ///< the pose solver's per-match arrays, and the drift check's
  size_t contrast_memory = 0;  ///< the last trusted frame's contrasts

  /// One buffer, named as the tables name it.
  struct Row {
    const char* name;
    size_t bytes;
  };
  std::array<Row, 8> rows() const {
    return {{{"model", model},
             {"edge_id_image", edge_id_image},
             {"edge_id_lines", edge_id_lines},
             {"grey_image", grey_image},
             {"control_points", control_points},
             {"matches", matches},
             {"pose_workspace", pose_workspace},
             {"contrast_memory", contrast_memory}}};
  }
  /// Together; what else the tracker holds (the moving edges' masks, the faces' states, the
  /// grey boxes' row spans, the state object itself) is the allocator's count minus this.
  size_t total() const {
    size_t sum = 0;
    for (const Row& row : rows()) sum += row.bytes;
    return sum;
  }
};

}  // namespace edgetrack
