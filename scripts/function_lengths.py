#!/usr/bin/env python3
"""Function lengths of plantsim's own C++ (tests aside): prints every function body longer than
the limit and exits 1 if any is not one of the named data tables. Usage:
  scripts/function_lengths.py [--limit 80] [--all] [DIR...]
A body is counted from the line of its opening brace to the line of its closing one; a lambda
counts within the function that holds it. Comments, strings and raw strings are blanked first, so
braces inside them do not count."""
import argparse
import os
import re
import sys

# Functions that are data tables (one row per parameter or per case), at most three: splitting
# them would scatter one table over several functions. Keyed by file and function name.
DATA_TABLES = {
    ("episode/episode_config_json.cpp", "fields"),
}

MODULES = ["app", "batch", "bench", "controller", "episode", "fuzz", "geometry", "planner", "python", "render",
           "robot", "sim", "util", "worlds"]

CONTROL = re.compile(r"\b(if|for|while|switch|catch)\s*\(")


def blank_comments_and_strings(src):
    out, i, n = [], 0, len(src)
    while i < n:
        if src.startswith("//", i):
            j = src.find("\n", i)
            j = n if j < 0 else j
        elif src.startswith("/*", i):
            j = src.find("*/", i) + 2
        elif src.startswith('R"', i) and not (i > 0 and (src[i - 1].isalnum() or src[i - 1] == "_")):
            m = re.match(r'R"([^(]*)\(', src[i:])
            end = ")" + m.group(1) + '"'
            j = src.find(end, i) + len(end)
        elif src[i] == '"' or (src[i] == "'" and not (i > 0 and src[i - 1].isalnum())):
            quote, j = src[i], i + 1
            while src[j] != quote:
                j += 2 if src[j] == "\\" else 1
            j += 1
        else:
            out.append(src[i])
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", src[i:j]))
        i = j
    return "".join(out)


def function_name(head):
    """The name before the parameter list that closes `head` (the text before a body's brace)."""
    close = head.rfind(")")
    depth = 0
    for i in range(close, -1, -1):
        depth += {")": 1, "(": -1}.get(head[i], 0)
        if depth == 0:
            name = re.search(r"([\w:~]+|operator\S+)\s*$", head[:i])
            return name.group(1) if name else "lambda"
    return "?"


def function_bodies(path):
    """(first line, line count, name) of each outermost function body in the file."""
    lines = blank_comments_and_strings(open(path, encoding="utf-8").read()).split("\n")
    stack, bodies = [], []
    for ln, line in enumerate(lines):
        for k, ch in enumerate(line):
            if ch == "{":
                before = (" ".join(lines[max(0, ln - 4):ln]) + " " + line[:k]).rstrip()
                tail = re.split(r"[;{}]", before)[-1]
                is_function = (re.search(r"\)\s*(const|override|noexcept|final|mutable|->[^;{}]*|\s)*$", tail)
                               and not CONTROL.search(tail))
                stack.append((ln, bool(is_function), function_name(tail)))
            elif ch == "}" and stack:
                start, is_function, name = stack.pop()
                if is_function and not any(s[1] for s in stack):
                    bodies.append((start + 1, ln - start + 1, name))
    return bodies


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--limit", type=int, default=80)
    ap.add_argument("--all", action="store_true", help="list every body over the limit, tables too")
    ap.add_argument("dirs", nargs="*")
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.chdir(root)
    too_long = []
    for module in args.dirs or MODULES:
        for dirpath, _, files in os.walk(module):
            for f in sorted(files):
                if not f.endswith((".cpp", ".h")):
                    continue
                path = os.path.join(dirpath, f)
                for first, count, name in function_bodies(path):
                    if count > args.limit:
                        too_long.append((count, path, first, name))
    failed = 0
    for count, path, first, name in sorted(too_long, reverse=True):
        table = (path, name) in DATA_TABLES
        if table and not args.all:
            continue
        failed += not table
        note = " (a data table)" if table else ""
        print(f"{path}:{first}: {name} is {count} lines{note}")
    if failed:
        print(f"function_lengths: {failed} functions over {args.limit} lines (docs/architecture.md)")
        return 1
    print(f"function_lengths: no function over {args.limit} lines outside tests "
          f"({len(DATA_TABLES)} data table)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
