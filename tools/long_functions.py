#!/usr/bin/env python3
"""Lists the functions of the C++ sources under the given folders longer than a limit (default 150 lines).

A function is a definition whose body opens with '{' at the end of a line and closes with '}' alone at the
same indentation (clang-format's layout in this project): free functions and member functions defined out of
class at namespace scope, and member functions defined in a class body. Lambdas count towards the function
they are in. Exit 1 when any function is longer than the limit, 0 otherwise.
    tools/long_functions.py src app [--limit 150]
"""
import argparse
import os
import re
import sys

OPENING = re.compile(r"^(\s*)(?=\S)(?!(namespace|class|struct|enum|union|extern|if|for|while|switch|do|else|try)\b)"
                     r"[^;#/]*\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(->\s*[^{]+)?\{\s*$")


def functions(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        m = OPENING.match(lines[i])
        if not m:
            i += 1
            continue
        # The signature may start on earlier lines: walk back to the line after the previous statement.
        start = i
        while start > 0 and lines[start - 1].strip() and not lines[start - 1].rstrip().endswith((";", "}", "{")) \
                and not lines[start - 1].lstrip().startswith(("//", "#")) \
                and lines[start - 1].strip() not in ("public:", "private:", "protected:"):
            start -= 1
        indent = re.match(r"\s*", lines[start]).group(0)
        closing = indent + "}"
        j = i + 1
        while j < len(lines) and not (lines[j].rstrip() == closing or lines[j].startswith(closing + ";")):
            if lines[j].strip() and not lines[j].startswith(indent) and indent:
                break
            j += 1
        name = lines[start].strip()
        yield start + 1, j - start + 1, name
        i = j + 1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="+")
    parser.add_argument("--limit", type=int, default=150)
    args = parser.parse_args()
    long_ones = []
    for folder in args.folders:
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if name.endswith((".cpp", ".hpp")):
                    path = os.path.join(root, name)
                    for line, length, signature in functions(path):
                        if length > args.limit:
                            long_ones.append((length, f"{path}:{line}", signature[:100]))
    for length, where, signature in sorted(long_ones, reverse=True):
        print(f"{where}: {length} lines: {signature}")
    if long_ones:
        print(f"{len(long_ones)} function(s) over {args.limit} lines", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
