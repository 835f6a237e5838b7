// SPDX-License-Identifier: BSD-3-Clause
/// ARM semihosting (Arm's "Semihosting for AArch32 and AArch64", v2.0): on M-profile a BKPT 0xAB
/// with the operation in r0 and its argument (a word or the address of a block of words) in r1;
/// the debugger or QEMU (-semihosting-config enable=on) performs it on the host.
#pragma once

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
  kSemihostOpen = 0x01,
  kSemihostClose = 0x02,
  kSemihostWrite0 = 0x04,
  kSemihostWrite = 0x05,
  kSemihostRead = 0x06,
  kSemihostSeek = 0x0A,
  kSemihostFileLength = 0x0C,
  kSemihostRemove = 0x0E,
  kSemihostRename = 0x0F,
  kSemihostClock = 0x10,
  kSemihostErrno = 0x13,
  kSemihostCommandLine = 0x15,
  kSemihostExitExtended = 0x20,
};

static inline intptr_t semihost_call(int op, const void* arg) {
  register intptr_t r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

/// Ends the program with `status` as the emulator's exit status (SYS_EXIT_EXTENDED,
/// ADP_Stopped_ApplicationExit).
__attribute__((noreturn)) void semihost_exit(int status);

#ifdef __cplusplus
}
#endif
