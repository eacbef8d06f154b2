#!/usr/bin/env python3
"""The layering of plantsim's modules, checked over every module at every build and as a test:
data flows one way, so a module may include and link only the modules before it in ORDER (and
itself); Box2D is the simulator's alone (nothing else includes it, so the robot's side cannot reach
the physics' truth); every top-level folder holding C++ is a module listed here or named as a
consumer of all (tests, fuzz harnesses), so a new module cannot slip past the check.
Usage: scripts/check_layering.py [ROOT]   (exit 1 naming each file, line and arrow that breaks it)"""
import os
import re
import sys

ORDER = ["util", "geometry", "worlds", "planner", "controller", "robot", "plugins", "sim", "episode", "render", "batch",
         "tune", "bench", "app", "python"]
CONSUMERS = {"tests", "fuzz"}  # may include and link every module; nothing includes them
NOT_CODE = {"build", "build-sanitize", "results", "docs", "scripts", "data", "configs", "examples", "cmake"}
BOX2D_OWNER = "sim"
# Libraries named otherwise than plantsim_<module>.
LIBRARY_MODULE = {"plantsim_app_lib": "app", "plantsim_convex_mesh": "planner", "plantsim_build_stamp": "util",
                  "plantsim_options": None, "plantsim_test": None, "plantsim_python": "python"}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([A-Za-z0-9_]+)/')
LINK = re.compile(r"target_link_libraries\s*\(\s*([A-Za-z0-9_]+)([^)]*)\)", re.S)


def sources(folder):
    for here, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for f in sorted(files):
            if f.endswith((".h", ".hpp", ".cpp", ".cc")):
                yield os.path.join(here, f)


def module_of_library(name):
    if name in LIBRARY_MODULE:
        return LIBRARY_MODULE[name]
    m = name[len("plantsim_"):] if name.startswith("plantsim_") else None
    return m if m in ORDER else None


def check_includes(root, module, errors):
    rank = ORDER.index(module)
    for path in sources(os.path.join(root, module)):
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = m.group(1)
                where = f"{os.path.relpath(path, root)}:{number}"
                if target == "box2d" and module != BOX2D_OWNER:
                    errors.append(f"{where}: {module}/ includes Box2D, which is {BOX2D_OWNER}/'s alone")
                elif target in CONSUMERS:
                    errors.append(f"{where}: {module}/ includes {target}/, which nothing may include")
                elif target in ORDER and ORDER.index(target) > rank:
                    errors.append(f"{where}: {module}/ includes {target}/, a module after it "
                                  f"({' -> '.join(ORDER)})")


def check_links(root, module, errors):
    rank = ORDER.index(module)
    for here, _, files in os.walk(os.path.join(root, module)):
        if "CMakeLists.txt" not in files:
            continue
        path = os.path.join(here, "CMakeLists.txt")
        text = open(path, encoding="utf-8").read()
        for m in LINK.finditer(text):
            number = text.count("\n", 0, m.start()) + 1
            for token in re.findall(r"\bplantsim_[A-Za-z0-9_]+", m.group(2)):
                target = module_of_library(token)
                if target is not None and ORDER.index(target) > rank:
                    errors.append(f"{os.path.relpath(path, root)}:{number}: {m.group(1)} links {token} "
                                  f"({target}/, a module after {module}/)")


def check_every_folder_is_known(root, errors):
    for entry in sorted(os.listdir(root)):
        folder = os.path.join(root, entry)
        if (not os.path.isdir(folder) or entry.startswith(".") or entry in ORDER or entry in CONSUMERS
                or entry in NOT_CODE or entry.startswith("build")):
            continue
        if any(True for _ in sources(folder)):
            errors.append(f"{entry}/: C++ in a folder the layering does not know: add it to ORDER "
                          f"(or CONSUMERS) in scripts/check_layering.py")


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    errors = []
    for module in ORDER:
        if not os.path.isdir(os.path.join(root, module)):
            errors.append(f"{module}/: listed in ORDER but missing")
            continue
        check_includes(root, module, errors)
        check_links(root, module, errors)
    check_every_folder_is_known(root, errors)
    for e in errors:
        print("layering: " + e, file=sys.stderr)
    if not errors:
        print(f"layering: {len(ORDER)} modules, includes and links one way ({' -> '.join(ORDER)})")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
