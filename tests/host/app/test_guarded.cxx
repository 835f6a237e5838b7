// SPDX-License-Identifier: BSD-3-Clause
// No exception leaves main: run_guarded turns whatever a command throws into one line and exit 1.
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>

#include "guarded.h"
#include "testlib/testlib_test.h"

using edgetrack_app::run_guarded;

static int returns_three(int, char**) { return 3; }
static int throws_bad_alloc(int, char**) { throw std::bad_alloc(); }
static int throws_runtime_error(int, char**) { throw std::runtime_error("something broke"); }
static int throws_filesystem_error(int, char**) {
  (void)std::filesystem::file_size(std::string(APP_TEST_TMP) + "/no/such/file");  // the throwing form
  return 0;
}
static int throws_an_int(int, char**) { throw 42; }

/// What run_guarded printed for `run`, and its status.
static std::string guarded_output(int (*run)(int, char**), int& status) {
  std::FILE* err = std::tmpfile();
  status = run_guarded("test", run, 0, nullptr, err);
  std::rewind(err);
  char line[512] = {0};
  std::string text;
  while (std::fgets(line, sizeof line, err)) text += line;
  std::fclose(err);
  return text;
}

static bool one_line(const std::string& text) {
  return !text.empty() && text.find('\n') == text.size() - 1;
}

static void test_guarded() {
  int status = 0;
  std::string text = guarded_output(returns_three, status);
  TEST_EQUAL("a command's own status passes through", status, 3);
  TEST("and nothing is printed", text.empty(), true);

  text = guarded_output(throws_bad_alloc, status);
  TEST_EQUAL("bad_alloc gives exit 1", status, 1);
  TEST("as one line saying out of memory", one_line(text) && text.find("edgetrack test: out of memory") == 0, true);

  text = guarded_output(throws_runtime_error, status);
  TEST_EQUAL("a std::exception gives exit 1", status, 1);
  TEST("as one line with its text", one_line(text) && text.find("internal error: something broke") != std::string::npos,
       true);

  text = guarded_output(throws_filesystem_error, status);
  TEST_EQUAL("a filesystem_error gives exit 1", status, 1);
  TEST("as one line naming the path", one_line(text) && text.find("no/such/file") != std::string::npos, true);

  text = guarded_output(throws_an_int, status);
  TEST_EQUAL("anything else thrown gives exit 1", status, 1);
  TEST("as one line", one_line(text) && text.find("unknown kind") != std::string::npos, true);
}

TESTMAIN(test_guarded)
