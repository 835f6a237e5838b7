// SPDX-License-Identifier: BSD-3-Clause
/// Reset and fault handling of the firmware images on mps2-an385: the vector table, .data copied
/// from flash and .bss zeroed, the stack painted (its high-water mark is measured, board.h), the
/// C and C++ constructors run, main called with the arguments semihosting passes, its status
/// returned to the host. A fault prints where it happened and ends the run with status 70.
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "board.h"
#include "semihosting.h"

extern uint32_t edgetrack_data_start[], edgetrack_data_end[], edgetrack_data_load[];
extern uint32_t edgetrack_bss_start[], edgetrack_bss_end[];
extern uint32_t edgetrack_stack_bottom[], edgetrack_stack_top[];
extern void __libc_init_array(void);
extern int main(int argc, char** argv);

void edgetrack_reset(void);
void edgetrack_fault(void);

enum { kStackPaint = 0x5eed57acu, kMaxArgs = 64, kCommandLineBytes = 4096 };

/// Cortex-M: the initial stack pointer, then the handlers; every exception other than reset is a fault here.
__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))edgetrack_stack_top, edgetrack_reset, edgetrack_fault, edgetrack_fault, edgetrack_fault,
    edgetrack_fault, edgetrack_fault, 0, 0, 0, 0, edgetrack_fault, edgetrack_fault, 0, edgetrack_fault,
    edgetrack_fault};

/// The C++ runtime's handle of this image for its destructors (no shared objects here), and the
/// empty _init/_fini that crti.o would give: constructors run from .init_array.
void* __dso_handle = &__dso_handle;
void _init(void) {}
void _fini(void) {}

static char command_line[kCommandLineBytes];
static char* arguments[kMaxArgs + 1];

/// Splits the semihosting command line (QEMU joins its arg= values with spaces) into argv.
static int read_arguments(void) {
  struct { char* buffer; int length; } block = {command_line, kCommandLineBytes};
  if (semihost_call(kSemihostCommandLine, &block) != 0) return 0;
  int argc = 0;
  for (char* p = command_line; *p && argc < kMaxArgs;) {
    while (*p == ' ') *p++ = '\0';
    if (!*p) break;
    arguments[argc++] = p;
    while (*p && *p != ' ') ++p;
  }
  arguments[argc] = NULL;
  return argc;
}

/// The stack in use now: the painted words below the deepest use stay paint.
static void paint_stack(void) {
  uint32_t* here = (uint32_t*)__builtin_frame_address(0) - 64;
  for (uint32_t* p = edgetrack_stack_bottom; p < here; ++p) *p = kStackPaint;
}

size_t edgetrack_stack_high_water(void) {
  const uint32_t* p = edgetrack_stack_bottom;
  while (p < edgetrack_stack_top && *p == kStackPaint) ++p;
  return (size_t)((const char*)edgetrack_stack_top - (const char*)p);
}

size_t edgetrack_static_ram(void) {
  return (size_t)((char*)edgetrack_bss_end - (char*)edgetrack_data_start);
}

/// With --board-report ahead of the program's name (run-firmware.sh, EDGETRACK_BOARD_REPORT=1),
/// the memory the run used, as one line on stderr when it ends.
static void report_memory(void) {
  fprintf(stderr, "board: static %lu bytes (.data and .bss), heap high-water %lu bytes, stack high-water %lu bytes\n",
          (unsigned long)edgetrack_static_ram(), (unsigned long)edgetrack_heap_high_water(),
          (unsigned long)edgetrack_stack_high_water());
}

void edgetrack_reset(void) {
  memcpy(edgetrack_data_start, edgetrack_data_load,
         (size_t)((char*)edgetrack_data_end - (char*)edgetrack_data_start));
  memset(edgetrack_bss_start, 0, (size_t)((char*)edgetrack_bss_end - (char*)edgetrack_bss_start));
  paint_stack();
  __libc_init_array();
  int argc = read_arguments();
  char** argv = arguments;
  if (argc > 0 && strcmp(argv[0], "--board-report") == 0) {
    atexit(report_memory);
    --argc;
    ++argv;
  }
  exit(main(argc, argv));
}

static char* put_hex(char* out, uint32_t value) {
  for (int shift = 28; shift >= 0; shift -= 4) *out++ = "0123456789abcdef"[(value >> shift) & 0xfu];
  return out;
}

static char* put_text(char* out, const char* text) {
  while (*text) *out++ = *text++;
  return out;
}

/// Prints the faulting PC, LR and fault status registers on the host's console, then ends the run.
/// Formats by hand: the fault may have come from the heap or the C library.
void edgetrack_fault(void) {
  uint32_t* frame;
  __asm__ volatile("tst lr, #4\n ite eq\n mrseq %0, msp\n mrsne %0, psp" : "=r"(frame));
  const volatile uint32_t* icsr = (const volatile uint32_t*)0xE000ED04u;
  const volatile uint32_t* cfsr = (const volatile uint32_t*)0xE000ED28u;
  const volatile uint32_t* hfsr = (const volatile uint32_t*)0xE000ED2Cu;
  char line[160];
  char* out = put_text(line, "firmware: fault, exception 0x");
  out = put_hex(out, *icsr & 0x1ffu);
  out = put_hex(put_text(out, " at pc 0x"), frame[6]);
  out = put_hex(put_text(out, " lr 0x"), frame[5]);
  out = put_hex(put_text(out, " CFSR 0x"), *cfsr);
  out = put_hex(put_text(out, " HFSR 0x"), *hfsr);
  out = put_text(out, "\n");
  *out = '\0';
  semihost_call(kSemihostWrite0, line);
  semihost_exit(70);
}
