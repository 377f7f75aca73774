#!/usr/bin/env python3
"""The layering rule of ARCHITECTURE.md, checked on every #include under src/ (and on the
installed plugin headers): a file may include its own layer and the layers below it, never
one above. Layers of equal rank (io and post; scenario and prep) may use each other.

Usage: layers.py SRC_DIR         check the tree
       layers.py --self-test     show the check catches an upward include
"""
import pathlib
import re
import sys

# Lowest first. The same list, in words, is in ARCHITECTURE.md ("Layers").
LAYERS = [
    ["engine"],
    ["models"],
    ["io", "post"],
    ["scenario", "prep"],
    ["studies"],
    ["cli"],
]
RANK = {name: rank for rank, names in enumerate(LAYERS) for name in names}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_0-9]+)/')


def violations(files):
    """files: iterable of (path relative to src, text). Returns (path, line, message)."""
    found = []
    for rel, text in files:
        own = rel.split("/")[0]
        if own not in RANK:
            found.append((rel, 0, f"folder '{own}' is in no layer; add it to LAYERS"))
            continue
        for n, line in enumerate(text.splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or m.group(1) not in RANK:
                continue
            if RANK[m.group(1)] > RANK[own]:
                found.append((rel, n, f"'{own}' includes '{m.group(1)}', a layer above it"))
    return found


def tree(src):
    src = pathlib.Path(src)
    for p in sorted(src.rglob("*")):
        if p.suffix in (".hpp", ".cpp") and p.is_file():
            yield str(p.relative_to(src)), p.read_text()


def self_test():
    good = [("models/x.cpp", '#include "engine/model.hpp"\n#include "models/y.hpp"\n'),
            ("io/a.cpp", '#include "post/b.hpp"\n'), ("post/b.cpp", '#include "io/a.hpp"\n')]
    bad = [("models/x.cpp", '#include "engine/model.hpp"\n#include "scenario/problem.hpp"\n'),
           ("engine/z.hpp", '  #  include "models/mplm/2d/attributes.hpp"\n'),
           ("io/w.cpp", '#include "cli/commands.hpp"\n'), ("newlayer/q.cpp", "")]
    assert violations(good) == [], violations(good)
    got = violations(bad)
    assert [(p, n) for p, n, _ in got] == [("models/x.cpp", 2), ("engine/z.hpp", 1),
                                           ("io/w.cpp", 1), ("newlayer/q.cpp", 0)], got
    print("self-test: 4 upward includes caught, 0 false alarms")


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return 0
    found = violations(tree(sys.argv[1]))
    for rel, n, msg in found:
        print(f"src/{rel}:{n}: {msg}")
    print(f"{'ok' if not found else 'FAILED'}: {len(found)} upward include(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
