#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes tests/bench/ports/upstream_api.tsv: per upstream vnl and vnl_algo header (the
headers upstream_vxl.tsv lists), how many of its public declarations ours has with the same
signature, and each one ours lacks or declares with another signature (tests/bench/api_decls.py
says how declarations are read and compared). Runs where a VXL checkout at upstream_vxl.tsv's
commit exists, not in CI: it only reads upstream's headers (parsed with clang -fsyntax-only,
after filling upstream's CMake-configured headers with this machine's values in a temporary
folder); nothing of upstream's is written out but names and signatures.
Usage: tests/bench/ports/upstream_api.py VXL_CHECKOUT BUILD_DIR > tests/bench/ports/upstream_api.tsv
(BUILD_DIR: a configured host double tree, for our generated headers)."""
import os
import re
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", "..", ".."))
sys.path.insert(0, os.path.join(top, "tests", "bench"))
import api_decls  # noqa: E402

# Values for the @VAR@ of upstream's configured headers on an LP64 little-endian host.
CONFIG = {"VXL_LITTLE_ENDIAN": "1", "VXL_BIG_ENDIAN": "0", "VXL_BYTE": "char", "VXL_INT_8": "char",
          "VXL_INT_16": "short", "VXL_INT_32": "int", "VXL_INT_64": "long", "VXL_IEEE_32": "float",
          "VXL_IEEE_64": "double", "VXL_IEEE_96": "", "VXL_IEEE_128": "", "VXL_HAS_IEEE_96": "0",
          "VXL_HAS_IEEE_128": "0", "VXL_ADDRESS_BITS": "64", "VNL_CONFIG_THREAD_SAFE": "1",
          "VXL_INT_64_IS_LONG": "1"}


def configure(src, dst):
    text = open(src).read()
    text = re.sub(r"#cmakedefine01 (\w+)", r"#define \1 0", text)
    text = re.sub(r"#cmakedefine (\w+)[^\n]*", r"/* #undef \1 */", text)
    text = re.sub(r"@(\w+)@", lambda m: CONFIG.get(m.group(1), "1" if "_HAS_" in m.group(1) else "0"), text)
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    open(dst, "w").write(text)


def listed_headers(lib):
    listed = [l.rstrip("\n").split("\t") for l in open(os.path.join(here, "upstream_vxl.tsv"))
              if not l.startswith("#")]
    return [p for l, kind, p in listed if l == lib and kind == "header" and p.endswith(".h")]


def include_name(lib, path):
    return ("vnl/" if lib == "vnl" else "vnl/algo/") + os.path.basename(path)


def parse_upstream(vxl, lib):
    """Upstream's declarations in lib's headers, and clang's errors, read through a temporary
    folder holding upstream's configured headers filled with this machine's values."""
    with tempfile.TemporaryDirectory() as shim:
        configure(os.path.join(vxl, "core/vnl/vnl_config.h.in"), os.path.join(shim, "vnl/vnl_config.h"))
        configure(os.path.join(vxl, "vcl/vcl_compiler.h.in"), os.path.join(shim, "vcl_compiler.h"))
        configure(os.path.join(vxl, "core/vxl_config.h.in"), os.path.join(shim, "vxl_config.h"))
        for name, macro in (("vnl/vnl_export.h", "VNL"), ("vnl/algo/vnl_algo_export.h", "VNL_ALGO")):
            os.makedirs(os.path.dirname(os.path.join(shim, name)), exist_ok=True)
            open(os.path.join(shim, name), "w").write(
                "#pragma once\n#define %s_EXPORT\n#define %s_TEMPLATE_EXPORT\n" % (macro, macro))
        flags = ["-I" + shim, "-I" + os.path.join(vxl, "core"), "-I" + os.path.join(vxl, "vcl"),
                 "-I" + os.path.join(vxl, "v3p/netlib")]
        include_as = {os.path.join(vxl, p): include_name(lib, p) for p in listed_headers(lib)}
        decls, _, errors = api_decls.parse(sorted(include_as), flags, include_as)
    return decls, errors, include_as


def upstream_declarations(vxl):
    """Every declaration of upstream's vnl and vnl_algo headers."""
    return [d for lib in ("vnl", "vnl_algo") for d in parse_upstream(vxl, lib)[0]]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.rsplit("Usage: ", 1)[1])
    vxl, build = (os.path.abspath(a) for a in sys.argv[1:])
    if not os.path.isfile(os.path.join(vxl, "core/vnl/vnl_matrix.h")):
        sys.exit("upstream_api: %s: no core/vnl/vnl_matrix.h (not a VXL checkout)" % vxl)
    commit = re.search(r"at commit ([0-9a-f]+)", open(os.path.join(here, "upstream_vxl.tsv")).read()).group(1)
    our_flags = ["-I" + os.path.join(top, p) for p in
                 ("ports/vnl/include", "ports/vcl/include", "ports/real/include", "ports/netlib/include")]
    our_flags += ["-I" + os.path.join(build, p) for p in ("ports/vcl/include", "ports/real/include")]
    print("# Upstream vnl and vnl_algo headers' public declarations (vxl/vxl %s) against ours,"
          % commit[:12])
    print("# written by tests/bench/ports/upstream_api.py. Columns: header, status, declaration"
          " (status total: counts).")
    for lib in ("vnl", "vnl_algo"):
        up_decls, up_errors, up_include_as = parse_upstream(vxl, lib)
        our_include_as = {}
        for p in listed_headers(lib):
            mine = os.path.join(top, "ports/vnl/include", include_name(lib, p))
            if os.path.exists(mine):
                our_include_as[mine] = include_name(lib, p)
        our_decls, our_aliases, our_errors = api_decls.parse(sorted(our_include_as), our_flags, our_include_as)
        for e in up_errors[:20] + our_errors[:20]:
            print("upstream_api: %s" % e, file=sys.stderr)
        rows = api_decls.compare(up_decls, our_decls, our_aliases, [up_include_as[k] for k in sorted(up_include_as)],
                                 lambda h: h if h in our_include_as.values() else None,
                                 our_flags, our_include_as)
        for header, status, decl in rows:
            print("%s\t%s\t%s" % (header, status, decl))


if __name__ == "__main__":
    main()
