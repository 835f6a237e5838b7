#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes tests/bench/visp_coverage/signatures.tsv: per ViSP 3.5 header that ports/visp has
(the ME module's and the core classes they use), how many of upstream's public declarations
ours has with the same signature, and each one ours lacks or declares with another signature
(tests/bench/api_decls.py says how declarations are read and compared). Upstream's headers are
Debian's libvisp-dev, read without VISP_BUILD_DEPRECATED_FUNCTIONS (the deprecated members are
not counted); ours are compared in the double build, where `real` is double.
Usage: tests/bench/visp_coverage/signatures.py BUILD_DIR [VISP_INCLUDE] > tests/bench/visp_coverage/signatures.tsv
(BUILD_DIR: a configured host double tree; VISP_INCLUDE defaults to /usr/include/x86_64-linux-gnu)."""
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", "..", ".."))
sys.path.insert(0, os.path.join(top, "tests", "bench"))
import api_decls  # noqa: E402


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.rsplit("Usage: ", 1)[1])
    build = os.path.abspath(sys.argv[1])
    upstream = os.path.abspath(sys.argv[2]) if len(sys.argv) == 3 else "/usr/include/x86_64-linux-gnu"
    if not os.path.isfile(os.path.join(upstream, "visp3/me/vpMe.h")):
        sys.exit("signatures: %s: no visp3/me/vpMe.h (ViSP's headers not there)" % upstream)
    ours_root = os.path.join(top, "ports/visp/include")
    names = sorted("visp3/%s/%s" % (module, h) for module in ("core", "me")
                   for h in os.listdir(os.path.join(ours_root, "visp3", module)) if h.endswith(".h"))
    names = [n for n in names if os.path.isfile(os.path.join(upstream, n))]
    up_include_as = {os.path.join(upstream, n): n for n in names}
    our_include_as = {os.path.join(ours_root, n): n for n in names}
    # ViSP's API without what Debian's build keeps for compatibility only (deprecated members,
    # some of them data members made public): the shim reads the real vpConfig.h, then drops it.
    shim = tempfile.mkdtemp()
    os.makedirs(os.path.join(shim, "visp3/core"))
    with open(os.path.join(shim, "visp3/core/vpConfig.h"), "w") as f:
        f.write("#include_next <visp3/core/vpConfig.h>\n#undef VISP_BUILD_DEPRECATED_FUNCTIONS\n")
    up_flags = ["-I" + shim, "-I" + upstream, "-isystem", "/usr/include/opencv4", "-isystem", "/usr/include/eigen3"]
    our_flags = ["-I" + os.path.join(top, p) for p in ("ports/visp/include", "ports/real/include", "ports/vnl/include",
                                                       "ports/vcl/include")]
    our_flags += ["-I" + os.path.join(build, p) for p in ("ports/real/include", "ports/vcl/include")]
    up_decls, _, up_errors = api_decls.parse(sorted(up_include_as), up_flags, up_include_as)
    our_decls, our_aliases, our_errors = api_decls.parse(sorted(our_include_as), our_flags, our_include_as)
    shutil.rmtree(shim)
    for e in up_errors[:20] + our_errors[:20]:
        print("signatures: %s" % e, file=sys.stderr)
    version = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "libvisp-core-dev"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False).stdout.decode()
    print("# ViSP's public declarations (libvisp-dev %s) against ports/visp's, written by"
          % (version or "version unknown"))
    print("# tests/bench/visp_coverage/signatures.py. Columns: header, status, declaration (status total: counts).")
    rows = api_decls.compare(up_decls, our_decls, our_aliases, names, lambda h: h, our_flags, our_include_as,
                             scalar=api_decls.doubles)
    for header, status, decl in rows:
        print("%s\t%s\t%s" % (header, status, decl))


if __name__ == "__main__":
    main()
