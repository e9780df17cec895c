#!/usr/bin/python3
"""Worst-case stack depth of call chains from the GCC call-graph files.

Reads every *.ci file (from -fcallgraph-info=su, the `make firmware` build)
under the given directory, builds the static call graph with each function's
own frame size, and prints the deepest chain from each root function.
Functions outside the core (libm, memset) have no frame information and are
listed with the allowance given by --extern-bytes (their frames are small
leaf frames in newlib; state the allowance with the figure).

  /usr/bin/python3 tests/support/stack_usage.py build/arm/obj/src fnav_nav_step fnav_nav_pop
"""
import glob
import re
import sys


def parse(d):
    frames, edges, names = {}, {}, {}
    for path in glob.glob(d + "/*.ci"):
        text = open(path).read()
        for m in re.finditer(r'node: \{ title: "([^"]+)" label: "([^"]*)"', text):
            title, label = m.group(1), m.group(2)
            fm = re.search(r"\\n(\d+) bytes", label)
            if fm:
                frames[title] = int(fm.group(1))
            elif title not in frames:
                frames[title] = None  # declared here, defined elsewhere (or external)
            names[title] = label.split("\\n")[0]
        for m in re.finditer(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"', text):
            edges.setdefault(m.group(1), set()).add(m.group(2))
    return frames, edges, names


def worst(node, frames, edges, ext, memo, stack):
    if node in memo:
        return memo[node]
    if node in stack:
        raise SystemExit("recursion through %s" % node)
    own = frames.get(node)
    own = ext if own is None else own
    best, chain = 0, []
    for t in edges.get(node, ()):
        # an edge may name a global by its bare name: resolve to the node
        tgt = t
        d, c = worst(tgt, frames, edges, ext, memo, stack | {node})
        if d > best:
            best, chain = d, c
    memo[node] = (own + best, [node] + chain)
    return memo[node]


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    ext = 64
    for a in sys.argv[1:]:
        if a.startswith("--extern-bytes="):
            ext = int(a.split("=", 1)[1])
    d, roots = args[0], args[1:]
    frames, edges, names = parse(d)
    missing = 0
    for r in roots:
        if r not in frames:
            # an error, not a line among the figures (it exited 0)
            sys.stderr.write("%s: not found in %s/*.ci (build them with make firmware)\n" % (r, d))
            missing += 1
            continue
        total, chain = worst(r, frames, edges, ext, {}, frozenset())
        print("%s: worst-case stack %d bytes (external functions counted as %d bytes each)" % (r, total, ext))
        for n in chain:
            f = frames.get(n)
            print("    %-28s %s" % (names.get(n, n), "%d" % f if f is not None else "extern (%d)" % ext))
    if missing:
        sys.exit(1)


if __name__ == "__main__":
    main()
