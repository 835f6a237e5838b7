#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Public declarations of C++ headers, read with clang's front end, and their comparison.

Each side (upstream's headers, ours) is parsed by `clang++ -fsyntax-only -Xclang
-ast-dump=json` on one translation unit that includes every header of the side; the JSON
tree is walked and every public declaration whose source file is one of the side's headers
is kept: functions, methods, constructors, conversions and operators with their type as clang
prints it (return and parameter types, const, static), public data members and variables,
typedefs and aliases. Default arguments, noexcept, virtual and attributes are not compared.

An upstream declaration is `found` when ours declares the same scope, name and signature in
a file that our header of the same name includes (directly or not), `compatible` when ours
takes the same calls (accepts(), special_member()), `via alias` when upstream's class is a
typedef of ours, `other signature` when ours has that scope and name only with other
signatures, and `missing` otherwise.

Limits: types are compared as spelled after normalisation, so a typedef spelled differently
on the two sides (`abs_t` against its underlying type) counts as another signature; template
parameters are renamed P<depth>_<position>; members of template specialisations are merged
under the template's name; declarations inside #if branches the parse does not take are not
seen.
"""
import json
import os
import re
import subprocess
import tempfile

FUNCTION_KINDS = {"FunctionDecl", "CXXMethodDecl", "CXXConstructorDecl", "CXXConversionDecl"}
SCOPE_KINDS = {"NamespaceDecl", "CXXRecordDecl", "ClassTemplateSpecializationDecl",
               "ClassTemplatePartialSpecializationDecl"}


class Walker:
    """Walks clang's JSON AST in document order: a location prints its file only when it
    differs from the previous one printed, so the current file is carried along."""

    def __init__(self, wanted):
        self.wanted = wanted  # absolute path -> header name
        self.file = None
        self.decls = []
        self.aliases = set()  # names a namespace-scope typedef or alias declares

    def _scan(self, value):
        if isinstance(value, dict):
            if "file" in value:
                self.file = value["file"]
            for key in ("spellingLoc", "expansionLoc", "begin", "end"):
                if key in value:
                    self._scan(value[key])

    def skip(self, node):
        """Carries the file along through a subtree whose declarations are not kept."""
        if isinstance(node, dict):
            for key, value in node.items():
                if key in ("loc", "range"):
                    self._scan(value)
                elif isinstance(value, (dict, list)):
                    self.skip(value)
        elif isinstance(node, list):
            for item in node:
                self.skip(item)

    def walk(self, node, scope, access, template=(), in_record=False):
        kind = node.get("kind", "")
        self._scan(node.get("loc"))
        here = os.path.realpath(self.file) if self.file else None
        self._scan(node.get("range"))
        inner = node.get("inner", [])
        public = access in (None, "public")
        keep = here in self.wanted and public and not node.get("isImplicit")
        name = node.get("name", "")
        if kind == "NamespaceDecl" and not name:
            self.skip(inner)  # an anonymous namespace is internal to its header
        elif kind == "NamespaceDecl":
            inner_scope = scope if node.get("isInline") or not name else scope + [name]
            self.walk_children(inner, inner_scope, None, template)
        elif kind == "LinkageSpecDecl":
            self.walk_children(inner, scope, None, template)
        elif kind in SCOPE_KINDS:
            if node.get("isImplicit") or not public or "completeDefinition" not in node:
                self.skip(inner)
                return
            default = "public" if node.get("tagUsed") in ("struct", "union") else "private"
            self.walk_children(inner, scope + [name], default, template, in_record=True)
        elif kind == "ClassTemplateDecl":
            self.walk_template(inner, ("CXXRecordDecl",), scope, access, template, in_record)
        elif kind == "FunctionTemplateDecl":
            self.walk_template(inner, FUNCTION_KINDS, scope, access, template, in_record)
        elif kind in FUNCTION_KINDS:
            # A member defined outside its class was declared inside it already.
            out_of_line = kind != "FunctionDecl" and not in_record
            if keep and not out_of_line:
                params = [p.get("type", {}).get("qualType", "") for p in inner
                          if p.get("kind") == "ParmVarDecl"]
                decl = self.record(here, scope, name, kind, node, params, template)
                if node.get("explicitlyDeleted"):
                    decl = decl[:3] + ("deleted",) + decl[4:]
                self.decls.append(decl)
            self.skip(inner)
        elif kind in ("VarDecl", "FieldDecl") and scope and keep:
            self.decls.append((self.wanted[here], "::".join(scope), name, "var",
                               normalise(node.get("type", {}).get("qualType", ""), template)))
            self.skip(inner)
        elif kind in ("TypedefDecl", "TypeAliasDecl") and keep:
            self.decls.append((self.wanted[here], "::".join(scope), name, "type", ""))
            if not scope:
                self.aliases.add(name)
            self.skip(inner)
        elif kind == "TypeAliasTemplateDecl" and keep:
            self.decls.append((self.wanted[here], "::".join(scope), name, "type", ""))
            self.skip(inner)
        else:
            self.skip(inner)

    def walk_template(self, inner, kinds, scope, access, template, in_record):
        """The parameters, then the pattern; the implicit instantiations that follow are skipped."""
        params = []
        for child in inner:
            if child.get("kind", "") in ("TemplateTypeParmDecl", "NonTypeTemplateParmDecl", "TemplateTemplateParmDecl"):
                self.skip(child)
                params.append(child.get("name") or "")
            elif child.get("kind") in kinds:
                self.walk(child, scope, access, template + (tuple(params),), in_record)
                params = None
            else:
                self.skip(child)
            if params is None:
                kinds = ()

    def walk_children(self, inner, scope, access, template=(), in_record=False):
        for child in inner:
            if child.get("kind") == "AccessSpecDecl":
                self._scan(child.get("loc"))
                self._scan(child.get("range"))
                access = child.get("access")
                continue
            self.walk(child, scope, access, template, in_record)

    def record(self, here, scope, name, kind, node, params, template):
        qual = node.get("type", {}).get("qualType", "")
        ret = qual.split("(", 1)[0].strip() if kind in ("FunctionDecl", "CXXMethodDecl") else ""
        tail = qual.rsplit(")", 1)[1] if ")" in qual else ""
        quals = " const" if re.search(r"\bconst\b", tail) else ""
        quals += " &&" if "&&" in tail else (" &" if "&" in tail else "")
        static = "static " if node.get("storageClass") == "static" and scope else ""
        if kind == "CXXConstructorDecl":
            name = scope[-1] if scope else name
        params = [re.sub(r"\s*\bconst$", "", p) for p in params]  # top-level const is no part of the type
        params = [p[6:] if p.startswith("const ") and not re.search(r"[&*]", p) else p for p in params]
        sig = "%s%s(%s)%s" % (static, (ret + " ") if ret else "", ", ".join(params), quals)
        return (self.wanted[here], "::".join(scope), re.sub(r"<.*", "", name) if kind == "CXXConstructorDecl" else name,
                "function", normalise(sig, template))


def normalise(sig, template=()):
    """Spelling differences that do not change the API. Template parameters are renamed by
    depth and position (P0_1: the second parameter of the outermost template)."""
    for depth, params in enumerate(template):
        for index, name in enumerate(params):
            if name:
                sig = re.sub(r"\b%s\b" % re.escape(name), "P%d_%d" % (depth, index), sig)
    sig = re.sub(r"type-parameter-(\d+)-(\d+)", r"P\1_\2", sig)
    sig = re.sub(r"\b(std|edgetrack_ports)::", "", sig)
    sig = re.sub(r"\bunsigned\b(?!\s+(int|char|short|long))", "unsigned int", sig)
    sig = re.sub(r"\s+", " ", sig).strip()
    sig = sig.replace(" &", "&").replace(" *", "*")
    return sig


def parse(headers, flags, include_as):
    """headers: absolute paths; include_as: the #include name of each. Returns declarations
    (header name, scope, name, kind, signature) and clang's first error lines."""
    wanted = {os.path.realpath(h): include_as[h] for h in headers}
    with tempfile.TemporaryDirectory() as tmp:
        tu = os.path.join(tmp, "all.cxx")
        with open(tu, "w") as f:
            for h in headers:
                f.write("#include <%s>\n" % include_as[h])
        run = subprocess.run(["clang++", "-std=c++17", "-fsyntax-only", "-ferror-limit=0",
                              "-Wno-everything", "-Xclang", "-ast-dump=json"] + flags + [tu],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, check=False)
    tree = json.loads(run.stdout)
    walker = Walker(wanted)
    walker.walk_children(tree.get("inner", []), [], None)
    errors = [l for l in run.stderr.decode(errors="replace").splitlines() if ": error:" in l]
    return walker.decls, walker.aliases, errors


def closure(header, flags, include_as):
    """The files a translation unit including `header` reads (clang -MM)."""
    run = subprocess.run(["clang++", "-std=c++17", "-MM", "-MG"] + flags +
                         ["-x", "c++", "-"], input=("#include <%s>\n" % include_as[header]).encode(),
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False)
    text = run.stdout.decode().replace("\\\n", " ")
    files = text.split(":", 1)[1].split() if ":" in text else []
    return {os.path.realpath(f) for f in files if os.path.exists(f)}


def split_params(sig):
    """(text before the parameter list, [parameters], text after) of a short signature."""
    open_at = sig.index("(")
    depth, parts, current = 0, [], ""
    for i, c in enumerate(sig[open_at + 1:], open_at + 1):
        if c in "(<":
            depth += 1
        elif c in ")>" and depth > 0:
            depth -= 1
        elif c == ")" or (c == "," and depth == 0):
            parts.append(current.strip())
            current = ""
            if c == ")":
                return sig[:open_at], [p for p in parts if p], sig[i + 1:]
            continue
        current += c
    return sig, [], ""


def loose(sig):
    """A parameter passed as `const X&` accepts what one passed by value accepts, and one of
    size_t what one of unsigned int does."""
    if "(" not in sig:
        return sig
    head, params, tail = split_params(sig)
    params = [p[6:-1] if p.startswith("const ") and p.endswith("&") and not p.endswith("&&") else p
              for p in params]
    params = [re.sub(r"\b(size_t|unsigned long)\b", "unsigned int", p) for p in params]
    return "%s(%s)%s" % (head, ", ".join(params), tail)


def accepts(ours, upstream):
    """True when our (possibly template) declaration takes the calls upstream's does: our
    template parameters stand for any type (the same one wherever the same parameter appears),
    a const method of ours for upstream's non-const one, `const X&` of ours for upstream's `X&`."""
    if "(" not in ours or "(" not in upstream:
        return False
    head, params, tail = split_params(upstream)
    if not tail.strip().startswith("const"):
        ours = re.sub(r"\)\s*const(\s*&*)$", r")\1", ours)
    as_const = [("const " + p) if p.endswith("&") and not p.endswith("&&") and not p.startswith("const ") else p
                for p in params]
    for variant in (upstream, "%s(%s)%s" % (head, ", ".join(as_const), tail)):
        pattern, seen = "", {}
        for piece in re.split(r"(P\d+_\d+)", re.escape(loose(ours))):
            if re.fullmatch(r"P\d+_\d+", piece):
                if piece in seen:
                    pattern += "(?P=%s)" % seen[piece]
                else:
                    seen[piece] = "g%d" % len(seen)
                    pattern += "(?P<%s>.+?)" % seen[piece]
            else:
                pattern += piece
        if re.fullmatch(pattern, loose(variant)) is not None:
            return True
    return False


def special_member(decl):
    """Copy and move constructors and assignments, which a class of ours has implicitly when
    it declares none (clang lists implicit members only where a use declared them)."""
    scope, name, kind, sig = decl[1], decl[2], decl[3], decl[4]
    cls = scope.split("::")[-1] if scope else ""
    if kind != "function" or not cls or "(" not in sig:
        return False
    _, params, _ = split_params(sig)
    if len(params) != 1 or not re.fullmatch(r"(const )?%s(<[^()]*>)?&{1,2}" % re.escape(cls), params[0]):
        return False
    return name in (cls, "operator=")


def compare(up_decls, our_decls, our_aliases, up_headers, our_header_of, our_flags, our_include_as,
            scalar=lambda sig: sig):
    """Rows (header, status, short declaration) for each upstream declaration ours does not
    have with the same signature, and (header, "total", counts) per header. Statuses: found
    (same signature), compatible (ours takes the same calls: see accepts() and special_member()), via alias (upstream's class is a typedef of ours: its members are those
    of the aliased class, not compared), other signature, missing."""
    by_file = {}
    for d in our_decls:
        by_file.setdefault(d[0], []).append(d)
    our_path = {v: k for k, v in our_include_as.items()}
    closures = {}
    rows = []
    for header in up_headers:
        mine = our_header_of(header)
        if mine in our_path and mine not in closures:
            closures[mine] = closure(our_path[mine], our_flags, our_include_as)
        visible = closures.get(mine, set())
        visible_names = {name for path, name in our_include_as.items() if os.path.realpath(path) in visible}
        ours = [(d[0], d[1], d[2], d[3], scalar(d[4])) for name in visible_names for d in by_file.get(name, [])]
        sigs = {d[1:] for d in ours if d[3] != "deleted"}
        deleted = {(d[1], d[2]) for d in ours if d[3] == "deleted"}
        ours = [d for d in ours if d[3] != "deleted"]
        by_name = {}
        for d in ours:
            by_name.setdefault((d[1], d[2]), []).append(d)
        counts = dict.fromkeys(("found", "compatible", "via alias", "other signature", "missing"), 0)
        seen = set()
        for d in up_decls:
            if d[0] != header or d[1:] in seen:
                continue
            seen.add(d[1:])
            short = "%s%s%s" % (d[1] + "::" if d[1] else "", d[2], "" if d[3] == "type" else " " + d[4])
            if d[1:] in sigs:
                status = "found"
            elif d[1] in our_aliases:
                status = "via alias"
            elif special_member(d) and (d[1], d[2]) not in deleted:
                status = "compatible"
            elif (d[1], d[2]) not in by_name:
                status = "missing"
            elif d[3] == "function" and any(o[3] == "function" and accepts(o[4], d[4]) for o in by_name[(d[1], d[2])]):
                status = "compatible"
            elif d[3] != "function":
                status = "found"  # a type or variable of that name: its spelling is not compared
            else:
                status = "other signature"
            counts[status] += 1
            if status in ("other signature", "missing"):
                rows.append((header, status, short))
        rows.append((header, "total", ", ".join("%s %d" % kv for kv in counts.items())))
    return rows


def doubles(sig):
    """Ours spells the scalar `real`; in the double build it is double."""
    return re.sub(r"\breal\b", "double", sig)
