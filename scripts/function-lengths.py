#!/usr/bin/env python3
"""Prints the longest C++ functions of the project, longest first.

A function is a body whose braces stand alone in column 0 (the layout of
VTK's style: the signature, then "{" and "}" on their own lines); its length
runs from the first line of the signature to the closing brace. Bodies of
namespaces, classes, structs, enums and unions are not functions.

    python3 scripts/function-lengths.py [--most N] [--over N] [PATH ...]

PATH: files or folders (default: the library's modules, Core, Scenes,
IO, Reference, Rendering and ParaView, without their tests). --over N exits with
status 1 when a function is longer than N lines.
"""
import argparse
import os
import re
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIBRARY = ["Core", "Scenes", "IO", "Reference", "Rendering", "ParaView"]
NOT_FUNCTIONS = re.compile(r"^\s*(namespace|class|struct|enum|union|extern)\b")


def sources(paths):
    for path in paths:
        if os.path.isfile(path):
            yield path
            continue
        for folder, subfolders, files in os.walk(path):
            subfolders[:] = sorted(d for d in subfolders if d != "Testing")
            for name in sorted(files):
                if name.endswith((".cxx", ".cpp", ".h")):
                    yield os.path.join(folder, name)


def signature_start(lines, brace):
    """The first line of the signature that ends just above line `brace`."""
    k = brace - 1
    while k > 0:
        previous = lines[k - 1].rstrip()
        if (not previous or previous.startswith(("}", "//", "#", "/*", " *", "*/"))
                or previous.endswith((";", "{", "*/"))):
            break
        k -= 1
    return k


def functions(path):
    with open(path, errors="replace") as f:
        lines = f.read().split("\n")
    open_line = None
    for i, line in enumerate(lines):
        if line.rstrip() == "{" and open_line is None:
            start = signature_start(lines, i)
            header = " ".join(l.strip() for l in lines[start:i])
            if header and not NOT_FUNCTIONS.match(header) and "(" in header:
                open_line = (start, header)
        elif line.startswith("}") and open_line is not None:
            start, header = open_line
            name = header.split("(")[0].split()[-1] if header.split("(")[0].split() else header
            yield i - start + 1, name, start + 1
            open_line = None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("paths", nargs="*")
    parser.add_argument("--most", type=int, default=15)
    parser.add_argument("--over", type=int, default=None)
    args = parser.parse_args()
    paths = args.paths or [os.path.join(REPO, p) for p in LIBRARY]
    found = []
    for path in sources(paths):
        for length, name, line in functions(path):
            found.append((length, name, os.path.relpath(path, REPO), line))
    found.sort(key=lambda f: (-f[0], f[2], f[3]))
    for length, name, path, line in found[:args.most]:
        print("%5d  %s  %s:%d" % (length, name, path, line))
    if args.over is not None:
        over = [f for f in found if f[0] > args.over]
        print("%d function(s) over %d lines" % (len(over), args.over))
        return 1 if over else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
