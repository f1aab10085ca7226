#!/usr/bin/env python3
"""Print the module dependency graph of the `garmentcode` and `garments` crates.

One node per source file (a folder's `mod.rs` is its own node). An edge `a -> b`
means file `a` names an item of module `b` through a `use` declaration or a
`crate::`/`super::`/`self::` path (including `pub use` re-exports of a child).
Declaring a child (`mod child;`) is not an edge. Paths are resolved to the longest
module prefix that is a file. The same rules are implemented by `tests/layering.rs`,
which asserts that the graphs are acyclic.

Usage: python3 tools/modgraph.py [crate_src_dir ...]   (default: both crates)
Prints, per crate: every module with its line count and the modules it depends on,
then any cycle found.
"""

import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = ["garmentcode/src", "garments/src"]


def strip(src):
    """Source with comments, string and char literals blanked (newlines kept)."""
    out = []
    i, n = 0, len(src)
    while i < n:
        c = src[i]
        if src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif src.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if src.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif src.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append("\n" * src.count("\n", i, j))
            i = j
        elif c == "r" and re.match(r'r#*"', src[i:]) and (i == 0 or not (src[i - 1].isalnum() or src[i - 1] == "_")):
            hashes = re.match(r'r(#*)"', src[i:]).group(1)
            end = src.find('"' + hashes, i + 2 + len(hashes))
            end = n if end < 0 else end + 1 + len(hashes)
            out.append('""' + "\n" * src.count("\n", i, end))
            i = end
        elif c == '"':
            j = i + 1
            while j < n and src[j] != '"':
                j += 2 if src[j] == "\\" else 1
            out.append('""' + "\n" * src.count("\n", i, j))
            i = j + 1
        elif c == "'":
            m = re.match(r"'(\\.|\\u\{[0-9a-fA-F]+\}|\\x[0-9a-fA-F]{2}|[^\\'])'", src[i:])
            if m:
                out.append("' '")
                i += len(m.group(0))
            else:  # a lifetime
                out.append(c)
                i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def module_of(rel):
    """Module path (list of names) of a file relative to the crate's src dir."""
    parts = rel[:-3].split("/")
    if parts[-1] in ("lib", "mod"):
        parts = parts[:-1]
    return parts


def expand_use(tree):
    """All paths of a use tree such as `a::{b, c::{d as e, self}}`."""
    tree = re.sub(r"\s+as\s+\w+", "", tree)
    tree = re.sub(r"\s+", "", tree)
    paths = []

    def walk(prefix, t):
        items, depth, cur = [], 0, ""
        for ch in t:
            if ch == "," and depth == 0:
                items.append(cur)
                cur = ""
                continue
            depth += ch == "{"
            depth -= ch == "}"
            cur += ch
        items.append(cur)
        for item in items:
            if not item:
                continue
            k = item.find("{")
            if k >= 0:
                head = item[:k].rstrip(":").split("::") if item[:k].rstrip(":") else []
                walk(prefix + head, item[k + 1 : item.rfind("}")])
            else:
                seg = item.split("::")
                seg = [s for s in seg if s]
                if seg and seg[-1] == "self":
                    seg = seg[:-1]
                paths.append(prefix + seg)

    walk([], tree)
    return paths


USE_RE = re.compile(r"\buse\s+([^;]+);")
PATH_RE = re.compile(r"(?<![\w:$])(\$?crate|super|self)((?:\s*::\s*\w+)+)")
MOD_RE = re.compile(r"\bmod\s+(\w+)\s*([;{])")


def inline_depths(text):
    """For each offset, how many inline `mod x { ... }` blocks enclose it."""
    depth_at = [0] * (len(text) + 1)
    stack, mods = [], 0
    starts = {m.end() - 1: True for m in MOD_RE.finditer(text) if m.group(2) == "{"}
    for i, ch in enumerate(text):
        if ch == "{":
            stack.append(i in starts)
            mods += i in starts
        elif ch == "}" and stack:
            mods -= stack.pop()
        depth_at[i] = mods
    return depth_at


def crate_graph(src_dir):
    files = {}
    for base, _, names in os.walk(src_dir):
        for name in names:
            if name.endswith(".rs"):
                path = os.path.join(base, name)
                files[os.path.relpath(path, src_dir).replace(os.sep, "/")] = path
    by_module = {tuple(module_of(rel)): rel for rel in files}
    lines, edges = {}, {rel: set() for rel in files}
    for rel, path in sorted(files.items()):
        with open(path, encoding="utf-8") as f:
            raw = f.read()
        lines[rel] = raw.count("\n")
        text = strip(raw)
        here = module_of(rel)
        depth_at = inline_depths(text)
        children = {m.group(1) for m in MOD_RE.finditer(text) if m.group(2) == ";"}
        refs = []
        for m in USE_RE.finditer(text):
            for p in expand_use(m.group(1)):
                refs.append((p, m.start()))
        for m in PATH_RE.finditer(text):
            segs = [m.group(1).lstrip("$")] + [s.strip() for s in m.group(2).split("::") if s.strip()]
            refs.append((segs, m.start()))
        for segs, at in refs:
            if not segs:
                continue
            inner = depth_at[at]
            if segs[0] == "crate":
                target = segs[1:]
            elif segs[0] in ("super", "self"):
                cur = here[:]
                # `self`/`super` inside an inline module start from that module.
                extra = inner
                i = 0
                while i < len(segs) and segs[i] in ("super", "self"):
                    if segs[i] == "super":
                        if extra:
                            extra -= 1
                        else:
                            cur = cur[:-1]
                    i += 1
                target = cur + segs[i:]
            elif segs[0] in children and inner == 0:
                target = here + segs
            else:
                continue
            best = None
            for k in range(len(target), -1, -1):
                if tuple(target[:k]) in by_module:
                    best = by_module[tuple(target[:k])]
                    break
            if best and best != rel:
                edges[rel].add(best)
    return lines, edges


def find_cycle(edges):
    """One cycle as a list of nodes, or None."""
    color, parent = {}, {}
    for start in sorted(edges):
        if start in color:
            continue
        stack = [(start, iter(sorted(edges[start])))]
        color[start] = 1
        while stack:
            node, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                color[node] = 2
                stack.pop()
            elif color.get(nxt) == 1:
                cycle = [nxt]
                for n, _ in reversed(stack):
                    cycle.append(n)
                    if n == nxt:
                        break
                return list(reversed(cycle))
            elif nxt not in color:
                color[nxt] = 1
                stack.append((nxt, iter(sorted(edges[nxt]))))
    return None


def main():
    dirs = sys.argv[1:] or [os.path.join(ROOT, d) for d in DEFAULT]
    for d in dirs:
        lines, edges = crate_graph(d)
        print(f"# {os.path.relpath(d, ROOT)}: {len(lines)} modules, {sum(lines.values())} lines")
        for rel in sorted(lines):
            deps = ", ".join(sorted(edges[rel])) or "-"
            print(f"{rel:34} {lines[rel]:5}  -> {deps}")
        cycle = find_cycle(edges)
        print("cycle: " + (" -> ".join(cycle) if cycle else "none"))
        print()


if __name__ == "__main__":
    main()
