// SPDX-License-Identifier: BSD-3-Clause
/// newlib's system calls on semihosting: files and the console through the host, the heap from
/// sbrk over the PSRAM (its high-water mark counted, board.h), exit with the program's status.
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <unistd.h>

#include "board.h"
#include "semihosting.h"

#undef errno
extern int errno;

enum { kMaxFiles = 16 };

/// Per descriptor: the host's handle and, to answer lseek(SEEK_CUR), the position (-1: not open).
static struct { intptr_t handle; long position; } files[kMaxFiles];
static int files_ready;

static void open_console(void) {
  // ":tt" opened for reading is stdin, for writing stdout, for appending stderr.
  static const int console_modes[3] = {0, 4, 8};
  for (int fd = 0; fd < kMaxFiles; ++fd) files[fd].handle = -1;
  for (int fd = 0; fd < 3; ++fd) {
    uintptr_t block[3] = {(uintptr_t) ":tt", (uintptr_t)console_modes[fd], 3};
    files[fd].handle = semihost_call(kSemihostOpen, block);
    files[fd].position = 0;
  }
  files_ready = 1;
}

static int host_errno(void) { return (int)semihost_call(kSemihostErrno, 0); }

static int checked_fd(int fd) {
  if (!files_ready) open_console();
  if (fd < 0 || fd >= kMaxFiles || files[fd].handle < 0) {
    errno = EBADF;
    return 0;
  }
  return 1;
}

int _open(const char* path, int flags, ...) {
  if (!files_ready) open_console();
  // Semihosting's fopen modes: r rb r+ r+b w wb w+ w+b a ab a+ a+b (binary is the odd ones).
  int mode = 1;
  const int access = flags & O_ACCMODE;
  if (flags & O_APPEND) mode = access == O_RDWR ? 11 : 9;
  else if (flags & O_TRUNC || (flags & O_CREAT && access != O_RDONLY)) mode = access == O_RDWR ? 7 : 5;
  else if (access == O_RDWR) mode = 3;
  int fd = 3;
  while (fd < kMaxFiles && files[fd].handle >= 0) ++fd;
  if (fd == kMaxFiles) {
    errno = EMFILE;
    return -1;
  }
  uintptr_t block[3] = {(uintptr_t)path, (uintptr_t)mode, strlen(path)};
  const intptr_t handle = semihost_call(kSemihostOpen, block);
  if (handle < 0) {
    errno = host_errno();
    return -1;
  }
  files[fd].handle = handle;
  files[fd].position = 0;
  return fd;
}

int _close(int fd) {
  if (!checked_fd(fd)) return -1;
  const intptr_t failed = fd < 3 ? 0 : semihost_call(kSemihostClose, &files[fd].handle);
  files[fd].handle = -1;
  if (failed) errno = host_errno();
  return failed ? -1 : 0;
}

int _read(int fd, char* buffer, int length) {
  if (!checked_fd(fd)) return -1;
  uintptr_t block[3] = {(uintptr_t)files[fd].handle, (uintptr_t)buffer, (uintptr_t)length};
  const intptr_t not_read = semihost_call(kSemihostRead, block);
  if (not_read < 0 || not_read > length) {
    errno = host_errno();
    return -1;
  }
  files[fd].position += length - not_read;
  return length - (int)not_read;
}

int _write(int fd, const char* buffer, int length) {
  if (!checked_fd(fd)) return -1;
  uintptr_t block[3] = {(uintptr_t)files[fd].handle, (uintptr_t)buffer, (uintptr_t)length};
  const intptr_t not_written = semihost_call(kSemihostWrite, block);
  if (not_written < 0 || not_written > length) {
    errno = host_errno();
    return -1;
  }
  files[fd].position += length - not_written;
  return length - (int)not_written;
}

static long file_length(int fd) { return (long)semihost_call(kSemihostFileLength, &files[fd].handle); }

int _lseek(int fd, int offset, int whence) {
  if (!checked_fd(fd)) return -1;
  long target = offset;
  if (whence == SEEK_CUR) target += files[fd].position;
  else if (whence == SEEK_END) target += file_length(fd);
  if (target < 0) {
    errno = EINVAL;
    return -1;
  }
  uintptr_t block[2] = {(uintptr_t)files[fd].handle, (uintptr_t)target};
  if (semihost_call(kSemihostSeek, block) != 0) {
    errno = host_errno();
    return -1;
  }
  files[fd].position = target;
  return (int)target;
}

int _fstat(int fd, struct stat* status) {
  if (!checked_fd(fd)) return -1;
  memset(status, 0, sizeof *status);
  if (fd < 3) {
    status->st_mode = S_IFCHR;
  } else {
    status->st_mode = S_IFREG;
    status->st_size = file_length(fd);
  }
  return 0;
}

int _isatty(int fd) { return fd >= 0 && fd < 3; }

int _unlink(const char* path) {
  uintptr_t block[2] = {(uintptr_t)path, strlen(path)};
  if (semihost_call(kSemihostRemove, block) == 0) return 0;
  errno = host_errno();
  return -1;
}

/// newlib's own rename() would link and unlink; semihosting renames in one call.
int rename(const char* from, const char* to) {
  uintptr_t block[4] = {(uintptr_t)from, strlen(from), (uintptr_t)to, strlen(to)};
  if (semihost_call(kSemihostRename, block) == 0) return 0;
  errno = host_errno();
  return -1;
}

/// Semihosting has no hard links.
int _link(const char* from, const char* to) {
  (void)from;
  (void)to;
  errno = EMLINK;
  return -1;
}

/// The host's clock since the run began, in its 10 ms steps (SYS_CLOCK).
int _gettimeofday(struct timeval* now, void* zone) {
  (void)zone;
  const intptr_t centiseconds = semihost_call(kSemihostClock, 0);
  now->tv_sec = centiseconds / 100;
  now->tv_usec = (centiseconds % 100) * 10000;
  return 0;
}

extern char edgetrack_heap_start[], edgetrack_heap_end[];
static char* heap_break = edgetrack_heap_start;
static char* heap_peak = edgetrack_heap_start;

void* _sbrk(ptrdiff_t increment) {
  if (increment > edgetrack_arena_end() - heap_break || increment < edgetrack_heap_start - heap_break) {
    errno = ENOMEM;
    return (void*)-1;
  }
  char* previous = heap_break;
  heap_break += increment;
  if (heap_break > heap_peak) heap_peak = heap_break;
  return previous;
}

size_t edgetrack_heap_high_water(void) { return (size_t)(heap_peak - edgetrack_heap_start); }

int _getpid(void) { return 1; }

int _kill(int pid, int signal) {
  (void)pid;
  (void)signal;
  semihost_exit(128 + signal);
}

void semihost_exit(int status) {
  uintptr_t block[2] = {0x20026, (uintptr_t)status};  // ADP_Stopped_ApplicationExit
  for (;;) semihost_call(kSemihostExitExtended, block);
}

void _exit(int status) { semihost_exit(status); }

/// What a path names, as far as semihosting tells: a file that opens for reading, and its length.
int _stat(const char* path, struct stat* status) {
  const int fd = _open(path, O_RDONLY);
  if (fd < 0) return -1;
  memset(status, 0, sizeof *status);
  status->st_mode = S_IFREG;
  status->st_size = file_length(fd);
  _close(fd);
  return 0;
}

// Semihosting has no directories, links or working directory: std::filesystem's calls of
// them fail with ENOSYS, which it reports as an error_code.
int mkdir(const char* path, mode_t mode) {
  (void)path;
  (void)mode;
  errno = ENOSYS;
  return -1;
}

ssize_t readlink(const char* path, char* buffer, size_t size) {
  (void)path;
  (void)buffer;
  (void)size;
  errno = ENOSYS;
  return -1;
}

int symlink(const char* target, const char* path) {
  (void)target;
  (void)path;
  errno = ENOSYS;
  return -1;
}

long pathconf(const char* path, int name) {
  (void)path;
  (void)name;
  errno = ENOSYS;
  return -1;
}

char* getcwd(char* buffer, size_t size) {
  (void)buffer;
  (void)size;
  errno = ENOSYS;
  return 0;
}
