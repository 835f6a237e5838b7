// SPDX-License-Identifier: BSD-3-Clause
/// QEMU TCG plugin (host shared library): counts the guest instructions a program executes, the
/// share of them inside libgcc's soft-float routines, and the same two counts inside the windows
/// the program marks with edgetrack_count_begin()/edgetrack_count_end(). Driven by
/// toolchains/qemu/count-insns.sh, which finds the addresses in the static binary's symbol table.
///
/// Arguments (`-plugin insn_count.so,key=value,...`):
///   ranges=<file>   lines "<start-hex> <end-hex>": the soft-float code, [start, end)
///   begin=<hex>     address of edgetrack_count_begin; end=<hex> of edgetrack_count_end
///   mode=tb|insn    tb (default): one inline add per translation block, which is exact because a
///                   block only stops early on a guest fault; insn: one inline add per instruction
///   out=<file>      where the summary line goes (default: QEMU's log, i.e. stderr)
///   windows=<file>  one line per closed window, in order
///   profile=<file>  one line per translated block that ran inside a window (or anywhere, without
///                   markers): "<start-hex> <instructions> <executions>"; count-insns.sh sums
///                   them per function. Costs a callback per executed block.
///
/// Summary line: `edgetrack-count total=N softfloat=N windows=N window_total=N
/// window_softfloat=N unbalanced=N`. A window counts from the first instruction of
/// edgetrack_count_begin up to, not including, the first instruction of edgetrack_count_end; nested
/// begin/end pairs count once, for the outermost pair; an end without a begin is `unbalanced`.
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qemu_plugin_api.h"

EDGETRACK_PLUGIN_EXPORT int qemu_plugin_version = kQemuPluginApiVersion;

typedef struct {
  uint64_t insns;
  uint64_t softfloat;
} Counts;

typedef struct {
  uint64_t start;
  uint64_t end;
} Range;

/// One translated block, for the profile: where it starts, its length, and how often it ran.
typedef struct {
  uint64_t start;
  uint64_t insns;
  uint64_t executions;
} Block;

typedef struct {
  // Updated by code QEMU emits inline: every executed instruction, and those in soft-float code.
  Counts all;
  // Window state, updated only when a marker function is entered.
  Counts at_begin;
  Counts in_windows;
  uint64_t windows;
  uint64_t depth;
  uint64_t unbalanced;
  Counts* window_log;
  size_t window_log_size;
  size_t window_log_capacity;
  Block** blocks;
  size_t blocks_size;
  size_t blocks_capacity;
  // Configuration.
  Range* softfloat;
  size_t softfloat_size;
  uint64_t begin_addr;
  uint64_t end_addr;
  int per_insn;
  const char* out_path;
  const char* windows_path;
  const char* profile_path;
} State;

static State state;

static int in_softfloat(uint64_t addr) {
  size_t lo = 0;
  size_t hi = state.softfloat_size;
  while (lo < hi) {  // first range whose end is above addr
    const size_t mid = lo + (hi - lo) / 2;
    if (state.softfloat[mid].end <= addr) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo < state.softfloat_size && state.softfloat[lo].start <= addr;
}

static int compare_ranges(const void* a, const void* b) {
  const Range* ra = a;
  const Range* rb = b;
  return ra->start < rb->start ? -1 : ra->start > rb->start;
}

/// Reads "<start> <end>" hex lines, sorts them and merges overlaps (aliases share addresses).
static int load_ranges(const char* path) {
  FILE* file = fopen(path, "r");
  if (!file) {
    fprintf(stderr, "insn_count: cannot open ranges file %s\n", path);
    return -1;
  }
  size_t capacity = 64;
  state.softfloat = malloc(capacity * sizeof(Range));
  uint64_t start = 0;
  uint64_t end = 0;
  while (fscanf(file, "%" SCNx64 " %" SCNx64 "%*[^\n]", &start, &end) == 2) {
    if (end <= start) continue;
    if (state.softfloat_size == capacity) {
      capacity *= 2;
      state.softfloat = realloc(state.softfloat, capacity * sizeof(Range));
    }
    state.softfloat[state.softfloat_size++] = (Range){start, end};
  }
  fclose(file);
  qsort(state.softfloat, state.softfloat_size, sizeof(Range), compare_ranges);
  size_t merged = 0;
  for (size_t i = 0; i < state.softfloat_size; ++i) {
    if (merged > 0 && state.softfloat[i].start <= state.softfloat[merged - 1].end) {
      if (state.softfloat[i].end > state.softfloat[merged - 1].end) {
        state.softfloat[merged - 1].end = state.softfloat[i].end;
      }
    } else {
      state.softfloat[merged++] = state.softfloat[i];
    }
  }
  state.softfloat_size = merged;
  return 0;
}

/// In tb mode the block's inline add has already counted the marker instruction and those after
/// it in its block when the marker's callback runs; `ahead` holds those counts, so that a snapshot
/// means "everything before the marker" in both modes.
static Counts before_marker(const Counts* ahead) {
  return (Counts){state.all.insns - ahead->insns, state.all.softfloat - ahead->softfloat};
}

static void on_begin(unsigned int vcpu_index, void* userdata) {
  (void)vcpu_index;
  if (state.depth++ == 0) state.at_begin = before_marker(userdata);
}

static void on_end(unsigned int vcpu_index, void* userdata) {
  (void)vcpu_index;
  if (state.depth == 0) {
    ++state.unbalanced;
    return;
  }
  if (--state.depth > 0) return;
  const Counts now = before_marker(userdata);
  const Counts window = {now.insns - state.at_begin.insns, now.softfloat - state.at_begin.softfloat};
  state.in_windows.insns += window.insns;
  state.in_windows.softfloat += window.softfloat;
  ++state.windows;
  if (!state.windows_path) return;
  if (state.window_log_size == state.window_log_capacity) {
    state.window_log_capacity = state.window_log_capacity ? 2 * state.window_log_capacity : 256;
    state.window_log = realloc(state.window_log, state.window_log_capacity * sizeof(Counts));
  }
  state.window_log[state.window_log_size++] = window;
}

/// Counts of the block's instructions from index `first` on (what tb mode adds before they run).
static Counts* block_tail(struct qemu_plugin_tb* tb, size_t first) {
  Counts* tail = calloc(1, sizeof(Counts));
  if (state.per_insn) return tail;
  const size_t n = qemu_plugin_tb_n_insns(tb);
  for (size_t i = first; i < n; ++i) {
    ++tail->insns;
    tail->softfloat += (uint64_t)in_softfloat(qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, i)));
  }
  return tail;
}

static void on_block(unsigned int vcpu_index, void* userdata) {
  (void)vcpu_index;
  if (state.depth > 0 || !state.begin_addr) ++((Block*)userdata)->executions;
}

/// A block translated again (QEMU retranslates) gets a record of its own; the script sums them.
static void profile_block(struct qemu_plugin_tb* tb) {
  Block* block = calloc(1, sizeof(Block));
  block->start = qemu_plugin_tb_vaddr(tb);
  block->insns = qemu_plugin_tb_n_insns(tb);
  if (state.blocks_size == state.blocks_capacity) {
    state.blocks_capacity = state.blocks_capacity ? 2 * state.blocks_capacity : 4096;
    state.blocks = realloc(state.blocks, state.blocks_capacity * sizeof(Block*));
  }
  state.blocks[state.blocks_size++] = block;
  qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS, block);
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb* tb) {
  (void)id;
  const size_t n = qemu_plugin_tb_n_insns(tb);
  uint64_t softfloat = 0;
  for (size_t i = 0; i < n; ++i) {
    struct qemu_plugin_insn* insn = qemu_plugin_tb_get_insn(tb, i);
    const uint64_t addr = qemu_plugin_insn_vaddr(insn);
    const int is_softfloat = in_softfloat(addr);
    softfloat += (uint64_t)is_softfloat;
    if (state.per_insn) {
      qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &state.all.insns, 1);
      if (is_softfloat) {
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &state.all.softfloat, 1);
      }
    }
    if (state.begin_addr && addr == state.begin_addr) {
      qemu_plugin_register_vcpu_insn_exec_cb(insn, on_begin, QEMU_PLUGIN_CB_NO_REGS, block_tail(tb, i));
    }
    if (state.end_addr && addr == state.end_addr) {
      qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, block_tail(tb, i));
    }
  }
  if (state.profile_path) profile_block(tb);
  if (!state.per_insn) {
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &state.all.insns, n);
    if (softfloat > 0) {
      qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &state.all.softfloat, softfloat);
    }
  }
}

static void write_profile(void) {
  FILE* file = fopen(state.profile_path, "w");
  if (!file) {
    fprintf(stderr, "insn_count: cannot write %s\n", state.profile_path);
    return;
  }
  for (size_t i = 0; i < state.blocks_size; ++i) {
    const Block* b = state.blocks[i];
    if (b->executions > 0) fprintf(file, "%" PRIx64 " %" PRIu64 " %" PRIu64 "\n", b->start, b->insns, b->executions);
  }
  fclose(file);
}

static void report_at_exit(qemu_plugin_id_t id, void* userdata) {
  (void)id;
  (void)userdata;
  char line[256];
  snprintf(line, sizeof line,
           "edgetrack-count total=%" PRIu64 " softfloat=%" PRIu64 " windows=%" PRIu64 " window_total=%" PRIu64
           " window_softfloat=%" PRIu64 " unbalanced=%" PRIu64 "\n",
           state.all.insns, state.all.softfloat, state.windows, state.in_windows.insns, state.in_windows.softfloat,
           state.unbalanced + state.depth);
  FILE* out = state.out_path ? fopen(state.out_path, "w") : NULL;
  if (out) {
    fputs(line, out);
    fclose(out);
  } else {
    if (state.out_path) fprintf(stderr, "insn_count: cannot write %s\n", state.out_path);
    qemu_plugin_outs(line);
  }
  if (state.profile_path) write_profile();
  if (state.windows_path) {
    FILE* log = fopen(state.windows_path, "w");
    if (!log) {
      fprintf(stderr, "insn_count: cannot write %s\n", state.windows_path);
      return;
    }
    for (size_t i = 0; i < state.window_log_size; ++i) {
      fprintf(log, "window %zu insns=%" PRIu64 " softfloat=%" PRIu64 "\n", i, state.window_log[i].insns,
              state.window_log[i].softfloat);
    }
    fclose(log);
  }
}

/// Returns the value of "key=value" when arg starts with key and '=', else NULL.
static const char* value_of(const char* arg, const char* key) {
  const size_t length = strlen(key);
  return strncmp(arg, key, length) == 0 && arg[length] == '=' ? arg + length + 1 : NULL;
}

EDGETRACK_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc,
                                                char** argv) {
  (void)info;
  for (int i = 0; i < argc; ++i) {
    const char* value = NULL;
    if ((value = value_of(argv[i], "ranges"))) {
      if (load_ranges(value) != 0) return -1;
    } else if ((value = value_of(argv[i], "begin"))) {
      state.begin_addr = strtoull(value, NULL, 16);
    } else if ((value = value_of(argv[i], "end"))) {
      state.end_addr = strtoull(value, NULL, 16);
    } else if ((value = value_of(argv[i], "mode"))) {
      if (strcmp(value, "tb") != 0 && strcmp(value, "insn") != 0) {
        fprintf(stderr, "insn_count: mode must be tb or insn, not %s\n", value);
        return -1;
      }
      state.per_insn = strcmp(value, "insn") == 0;
    } else if ((value = value_of(argv[i], "out"))) {
      state.out_path = value;
    } else if ((value = value_of(argv[i], "windows"))) {
      state.windows_path = value;
    } else if ((value = value_of(argv[i], "profile"))) {
      state.profile_path = value;
    } else {
      fprintf(stderr, "insn_count: unknown argument %s\n", argv[i]);
      return -1;
    }
  }
  qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
  qemu_plugin_register_atexit_cb(id, report_at_exit, NULL);
  return 0;
}
