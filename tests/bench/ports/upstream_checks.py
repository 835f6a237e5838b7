#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes tests/bench/ports/upstream_checks.tsv: per upstream vnl and vnl_algo test (the tests
upstream_vxl.tsv lists), how many of its checks our test of the same name covers. A check is a
TEST, TEST_NEAR, TEST_NEAR_REL, TEST_EQUAL, TEST_CONSTANT or testlib_test_assert* call; the
functions it exercises are the vnl and vnl_algo API names (functions, methods, constructors
by class name, from upstream's headers read as tests/bench/api_decls.py reads them) called in
its arguments or in the code since the previous check. It is covered when our test calls each
of those names somewhere. Names are matched as identifiers followed by `(` or `<`, outside
comments and strings, so a name several classes share (size, get) counts as one; operators
are not counted. Runs where a VXL checkout exists, not in CI; writes only counts and names.
Usage: tests/bench/ports/upstream_checks.py VXL_CHECKOUT BUILD_DIR > tests/bench/ports/upstream_checks.tsv"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", "..", ".."))
sys.path.insert(0, here)
import upstream_api  # noqa: E402

CHECK = re.compile(r"\b(TEST|TEST_NEAR|TEST_NEAR_REL|TEST_EQUAL|TEST_CONSTANT|testlib_test_assert\w*)\s*\(")
NOT_API = {"main", "operator"}


def code_only(text):
    """The source without comments, string and character literals."""
    return re.sub(r'//[^\n]*|/\*.*?\*/|"(\\.|[^"\\\n])*"|\'(\\.|[^\'\\\n])*\'', " ", text, flags=re.S)


def closing(text, start):
    depth = 0
    for k in range(start, len(text)):
        if text[k] == "(":
            depth += 1
        elif text[k] == ")":
            depth -= 1
            if depth == 0:
                return k
    return len(text)


def called(text, names):
    return {m.group(1) for m in re.finditer(r"\b([A-Za-z_]\w*)\s*[(<]", text) if m.group(1) in names}


def checks(text, names):
    """The API names each check exercises, in order."""
    text = code_only(text)
    found, previous_end = [], 0
    for m in CHECK.finditer(text):
        end = closing(text, m.end() - 1)
        found.append(called(text[previous_end:end], names))
        previous_end = end
    return found


def our_test(lib, name):
    folder = "tests/ports/vnl" if lib == "vnl" or name in ("test_levenberg_marquardt", "test_rank") else "tests/ports/vnl/algo"
    path = os.path.join(top, folder, name + ".cxx")
    return path if os.path.isfile(path) else None


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.rsplit("Usage: ", 1)[1])
    vxl = os.path.abspath(sys.argv[1])
    decls = upstream_api.upstream_declarations(vxl)
    names = {d[2] for d in decls if d[3] == "function" and not d[2].startswith("operator")} - NOT_API
    names |= {d[1].split("::")[-1] for d in decls if d[1]}
    listed = [l.rstrip("\n").split("\t") for l in open(os.path.join(here, "upstream_vxl.tsv")) if not l.startswith("#")]
    print("# Upstream vnl and vnl_algo tests' checks covered by ours, written by tests/bench/ports/upstream_checks.py.")
    print("# Columns: test, checks, covered, API names upstream's checks call and ours does not (checks calling each).")
    for lib, kind, path in listed:
        if kind != "test" or lib not in ("vnl", "vnl_algo") or not path.endswith(".cxx"):
            continue
        name = os.path.basename(path)[:-4]
        if not name.startswith("test_") or name in ("test_driver", "test_include", "test_template_include"):
            continue
        upstream_checks = checks(open(os.path.join(vxl, path), errors="replace").read(), names)
        mine = our_test(lib, name)
        ours = called(code_only(open(mine).read()), names) if mine else set()
        lacking = {}
        covered = 0
        for used in upstream_checks:
            missing = used - ours
            covered += not missing
            for n in missing:
                lacking[n] = lacking.get(n, 0) + 1
        gaps = ", ".join("%s (%d)" % (n, c) for n, c in sorted(lacking.items(), key=lambda kv: (-kv[1], kv[0])))
        print("%s\t%d\t%d\t%s" % (name, len(upstream_checks), covered, gaps if mine else "no test of ours"))


if __name__ == "__main__":
    main()
