// SPDX-License-Identifier: BSD-3-Clause
/// The tracker alone as a microcontroller's firmware (docs/MCU.md): no command line to parse, no
/// detector, no iostream. Its arguments, in this order, come by semihosting:
///   MODEL CAMERA.xml INIT.pos FRAMES FIRST LAST POSES.csv
/// FRAMES is a file name with one %d (%04d, ...) for the frame number; each frame is a binary
/// 8-bit PGM read into one camera buffer, where the tracker reads it in place as it would a
/// camera's DMA buffer. The poses CSV is the one `edgetrack track --poses` writes. At the end
/// the tracker's heap per buffer goes to stderr (tracker_memory.h), with the allocator's count.
#include <malloc.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>

#include "edgetrack/model_io.h"
#include "edgetrack/netpbm_header.h"
#include "edgetrack/pose_io.h"
#include "edgetrack/poses_csv.h"
#include "edgetrack/tracker.h"
#include "edgetrack/visp_config.h"
#include "board.h"
#include "count_markers.h"

namespace {

using edgetrack::Error;

/// The largest frame the camera buffer holds: QVGA, the budget.
constexpr int kMaxFrameWidth = 320, kMaxFrameHeight = 240;

/// What the tracker is created for: every buffer it needs is allocated then, from these, and the
/// heap is locked (board.h) before the first frame. A model with more primitives or a camera
/// larger than the frame buffer is refused at create; a frame that would sample more control
/// points is lost (over_limit) without a search.
constexpr edgetrack::TrackerLimits kTrackerLimits = [] {
  edgetrack::TrackerLimits limits;
  limits.primitives = 32;
  limits.control_points = EDGETRACK_MCU_MAX_CONTROL_POINTS;
  limits.image_width = kMaxFrameWidth;
  limits.image_height = kMaxFrameHeight;
  return limits;
}();

/// The camera's frame buffer: outside the RAM the firmware counts as its own (the linker script
/// puts .camera_frame beside the heap), as a camera's DMA buffer would be.
__attribute__((section(".camera_frame"))) unsigned char camera_frame[kMaxFrameWidth * kMaxFrameHeight];

int fail(const std::string& what) {
  std::fprintf(stderr, "tracker-firmware: %s\n", what.c_str());
  return 1;
}


/// newlib's printf of a double (dtoa) keeps the big-number blocks it allocates at first need, for
/// reuse: numbers of the poses CSV's formats over the magnitudes its columns take are printed once
/// before the heap is locked, so that writing the poses allocates nothing after it.
void prepare_number_formatting() {
  char text[64];
  for (double value = 1e-12; value < 1e12; value *= 10)
    for (double sign : {1.0, -1.0}) std::snprintf(text, sizeof text, "%.9g %.3f %.2f", sign * value, sign * value, sign * value);
}

/// What a failed allocation ends with (no exceptions): the arena is full, or the heap is locked.
[[noreturn]] void out_of_memory() {
  std::fputs("tracker-firmware: out of memory: the heap arena (EDGETRACK_MCU_ARENA_KB) is full, or the heap was "
             "locked\n", stderr);
  std::exit(1);
}

/// Bytes the C library's allocator has handed out and not yet taken back.
size_t live_heap() { return static_cast<size_t>(mallinfo().uordblks); }

/// A frame-name pattern with exactly one %d, with an optional 0 and width: %d, %04d.
bool one_number(const char* pattern) {
  int conversions = 0;
  for (const char* p = pattern; *p; ++p) {
    if (*p != '%') continue;
    ++p;
    while (std::isdigit(static_cast<unsigned char>(*p))) ++p;
    if (*p != 'd') return false;
    ++conversions;
  }
  return conversions == 1;
}

/// Reads a binary 8-bit PGM into camera_frame, of `width` x `height` when they are not 0 (the
/// first frame's); false, with its line on stderr (as Error::text() words it), when it cannot.
/// Nothing here allocates: the heap is locked after the first frame.
bool read_frame(const char* path, int& width, int& height) {
  std::FILE* file = std::fopen(path, "rb");
  if (!file) {
    std::fprintf(stderr, "tracker-firmware: %s: cannot open\n", path);
    return false;
  }
  std::setvbuf(file, nullptr, _IONBF, 0);  // no stdio buffer to allocate
  const edgetrack::NetpbmHeader h = edgetrack::parse_netpbm_header([file] { return std::fgetc(file); });
  const size_t pixels = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  bool read = false;
  if (!h.ok())
    std::fprintf(stderr, "tracker-firmware: %s:%d: %s\n", path, h.line, h.problem);
  else if (h.colour || h.ascii || h.maxval != 255)
    std::fprintf(stderr, "tracker-firmware: %s:%d: not a binary 8-bit PGM (P5, maxval 255)\n", path, h.line);
  else if (h.width < 1 || h.height < 1 || h.width > kMaxFrameWidth || h.height > kMaxFrameHeight)
    std::fprintf(stderr, "tracker-firmware: %s:%d: %dx%d is larger than the camera buffer's %dx%d\n", path, h.size_line,
                 h.width, h.height, kMaxFrameWidth, kMaxFrameHeight);
  else if (width != 0 && (h.width != width || h.height != height))
    std::fprintf(stderr, "tracker-firmware: %s:%d: %dx%d, not the first frame's %dx%d\n", path, h.size_line, h.width,
                 h.height, width, height);
  else if (std::fread(camera_frame, 1, pixels, file) != pixels)
    std::fprintf(stderr, "tracker-firmware: %s: the pixel data is truncated (%lu bytes expected after the header)\n",
                 path, (unsigned long)pixels);
  else
    read = true;
  std::fclose(file);
  width = h.width;
  height = h.height;
  return read;
}

/// The tracker's heap per buffer, the allocator's count of it after create and at the end, and
/// what else the heap held: the C library's own (live before the inputs were read: the open
/// poses file) and the allocator's free blocks within its arena at the end.
void report_memory(const edgetrack::TrackerMemory& m, size_t before, size_t created, size_t counted) {
  for (const auto& row : m.rows()) std::fprintf(stderr, "tracker memory: %s %lu bytes\n", row.name, (unsigned long)row.bytes);
  std::fprintf(stderr, "tracker memory: created %lu bytes (the allocator's, after Tracker::create)\n",
               (unsigned long)created);
  std::fprintf(stderr, "tracker memory: counted %lu bytes (the allocator's, after the last frame)\n",
               (unsigned long)counted);
  const struct mallinfo heap = mallinfo();
  std::fprintf(stderr, "heap: before the tracker %lu bytes, free within the arena %lu bytes, arena %lu bytes\n",
               (unsigned long)before, (unsigned long)heap.fordblks, (unsigned long)heap.arena);
}

/// The tracker of the model, camera and initial pose files argv[1..3], for frames of
/// width x height when the camera gives no size. What was read is freed on return: the tracker
/// keeps its own copies.
std::optional<edgetrack::Tracker> start_tracker(char** argv, int width, int height, std::string& problem) {
  auto model = edgetrack::load_model(argv[1]);
  if (!model.ok()) return problem = model.error().text(), std::nullopt;
  edgetrack::TrackerConfig config;
  auto read = edgetrack::apply_visp_config(argv[2], config);
  if (!read.ok()) return problem = read.error().text(), std::nullopt;
  auto initial = edgetrack::read_pos(argv[3]);
  if (!initial.ok()) return problem = initial.error().text(), std::nullopt;
  edgetrack::PinholeCamera camera = config.camera;
  if (camera.width == 0) camera.width = width;
  if (camera.height == 0) camera.height = height;
  auto made = edgetrack::Tracker::create(model.value(), camera, initial.value(), config.params, kTrackerLimits);
  if (!made.ok()) return problem = made.error().text(), std::nullopt;
  return std::move(made).value();
}

}  // namespace

int main(int argc, char** argv) {
  std::set_new_handler(out_of_memory);
  if (argc != 8)
    return fail("usage: tracker-firmware MODEL CAMERA.xml INIT.pos FRAMES FIRST LAST POSES.csv (FRAMES with one %d)");
  const char* frames = argv[4];
  char* end_first = nullptr;
  char* end_last = nullptr;
  const long first = std::strtol(argv[5], &end_first, 10), last = std::strtol(argv[6], &end_last, 10);
  if (*end_first || *end_last || first < 0 || last < first || last > 999999)
    return fail(std::string("the frame numbers ") + argv[5] + " and " + argv[6] + " are not FIRST <= LAST, both >= 0");
  if (!one_number(frames)) return fail(std::string(frames) + ": the frame name needs exactly one %d");

  std::FILE* poses = std::fopen(argv[7], "w");
  if (!poses) return fail(std::string(argv[7]) + ": cannot write");
  std::fprintf(poses, "%s\n", edgetrack::kPosesCsvHeader);

  const size_t before_tracker = live_heap();
  size_t created = 0, calls_at_lock = 0;
  std::optional<edgetrack::Tracker> tracker;
  char name[256];
  int width = 0, height = 0;
  char line[edgetrack::kPosesCsvLineBytes];
  std::string problem;
  for (long index = first; index <= last; ++index) {
    std::snprintf(name, sizeof name, frames, static_cast<int>(index));
    if (!read_frame(name, width, height)) return 1;
    const edgetrack::FrameView frame = edgetrack::packed_frame(camera_frame, width, height, edgetrack::PixelLayout::kGrey8);
    if (!tracker) {
      tracker = start_tracker(argv, width, height, problem);
      if (!tracker) return fail(problem);
      created = live_heap() - before_tracker;
      prepare_number_formatting();
      edgetrack_heap_lock();
      calls_at_lock = edgetrack_allocation_calls();
    }
    edgetrack_count_begin();  // the tracker's share of the frame (toolchains/qemu/count-insns.sh)
    auto result = tracker->track(frame);
    edgetrack_count_end();
    if (!result.ok()) return fail(Error{name, 0, result.error().message}.text());
    if (result.value().reason == edgetrack::StatusReason::kOverLimit)
      std::fprintf(stderr, "tracker-firmware: %s: lost: %s (%d)\n", name, edgetrack::reason_name(result.value().reason),
                   kTrackerLimits.control_points);
    edgetrack::poses_csv_line(edgetrack::poses_csv_row(static_cast<int>(index), result.value()), line);
    std::fprintf(poses, "%s\n", line);
  }
  if (std::fclose(poses) != 0) return fail(std::string(argv[7]) + ": writing failed");
  std::fprintf(stderr, "tracker limits: %d control points per frame, %d primitives, %dx%d\n", kTrackerLimits.control_points,
               kTrackerLimits.primitives, kTrackerLimits.image_width, kTrackerLimits.image_height);
  report_memory(tracker->memory(), before_tracker, created, live_heap() - before_tracker);
  const size_t after_lock = edgetrack_allocation_calls() - calls_at_lock;
  std::fprintf(stderr, "allocations: %lu until the tracker was created, %lu after it (%lu refused)\n",
               (unsigned long)calls_at_lock, (unsigned long)after_lock, (unsigned long)edgetrack_refused_allocations());
  if (after_lock > 0) return fail("the heap was used after the tracker was created");
  return 0;
}
