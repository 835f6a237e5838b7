// SPDX-License-Identifier: BSD-3-Clause
/// Our own declarations of the few QEMU TCG plugin API calls insn_count.c uses (plugin API
/// version 1, as exported by Debian 12's qemu-user 7.2, which ships no qemu-plugin.h). Written
/// from the documented API: the names, argument types and enum values must match QEMU's ABI.
#ifndef EDGETRACK_QEMU_PLUGIN_API_H
#define EDGETRACK_QEMU_PLUGIN_API_H

#include <stddef.h>
#include <stdint.h>

#define EDGETRACK_PLUGIN_EXPORT __attribute__((visibility("default")))

/// The API version this plugin is built against; QEMU reads the exported
/// `qemu_plugin_version` and refuses plugins outside its [min, cur] range.
enum { kQemuPluginApiVersion = 1 };

typedef uint64_t qemu_plugin_id_t;

/// What QEMU tells the plugin at install time (only valid during qemu_plugin_install).
typedef struct qemu_info_t {
  const char* target_name;
  struct {
    int min;
    int cur;
  } version;
  _Bool system_emulation;
  union {
    struct {
      int smp_vcpus;
      int max_vcpus;
    } system;
  };
} qemu_info_t;

struct qemu_plugin_tb;    // a translation block, opaque
struct qemu_plugin_insn;  // one translated guest instruction, opaque

enum qemu_plugin_cb_flags {
  QEMU_PLUGIN_CB_NO_REGS = 0,
  QEMU_PLUGIN_CB_R_REGS = 1,
  QEMU_PLUGIN_CB_RW_REGS = 2,
};

/// Inline operations QEMU emits into translated code; version 1 has only this one.
enum qemu_plugin_op {
  QEMU_PLUGIN_INLINE_ADD_U64 = 0,
};

typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void* userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void* userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb* tb);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb* tb, enum qemu_plugin_op op, void* ptr,
                                              uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn* insn, enum qemu_plugin_op op, void* ptr,
                                                uint64_t imm);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb* tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void* userdata);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn* insn, qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void* userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void* userdata);

size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb* tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb* tb);
struct qemu_plugin_insn* qemu_plugin_tb_get_insn(const struct qemu_plugin_tb* tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn* insn);

/// Writes a string through QEMU's log (stderr unless -D redirects it).
void qemu_plugin_outs(const char* string);

#endif  // EDGETRACK_QEMU_PLUGIN_API_H
