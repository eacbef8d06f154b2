#!/usr/bin/env python3
"""docs/config.md against the parameters an episode reads (`plantsim config`): every key the
table documents can be set, every key that can be set is documented, and every `section.key` the
prose names is one of them. A documented key that no reader knows is a user's setting refused (or,
worse, a scenario author's belief about a knob that does not exist).
Usage: scripts/check_config_docs.py PLANTSIM DOCS/CONFIG.MD   (exit 1 naming each key)"""
import json
import re
import subprocess
import sys

# `name.suffix` tokens in the prose that are not parameters: files, and the world's own fields.
NOT_PARAMETER = re.compile(r"\.(yaml|json|md|h|cpp|py|png|html|csv|jsonl)$|^charger\.")


def readable_keys(plantsim):
    config = json.loads(subprocess.run([plantsim, "config"], check=True, capture_output=True,
                                       text=True).stdout)

    def walk(prefix, node):
        for key, value in node.items():
            if isinstance(value, dict):
                yield from walk(prefix + key + ".", value)
            else:
                yield prefix + key
    return set(walk("", config))


def table_keys(lines):
    """A row's first cell: `section.key`, then keys of the same section by their short names."""
    keys = {}
    for number, line in enumerate(lines, 1):
        if not line.startswith("| `"):
            continue
        section = None
        for token in re.findall(r"`([^`]+)`", line.split("|")[1]):
            if "." in token:
                section = token.split(".", 1)[0]
                keys[token] = number
            elif section:
                keys[section + "." + token] = number
            else:
                keys[token] = number
    return keys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    plantsim, docs = sys.argv[1], sys.argv[2]
    with open(docs, encoding="utf-8") as f:
        lines = f.read().splitlines()
    readable = readable_keys(plantsim)
    documented = table_keys(lines)
    problems = [f"{docs}:{n}: documents `{k}`, which `plantsim config` does not have"
                for k, n in sorted(documented.items()) if k not in readable]
    problems += [f"{docs}: `{k}` can be set but is not documented" for k in sorted(readable - documented.keys())]
    sections = {k.split(".", 1)[0] for k in readable}
    for number, line in enumerate(lines, 1):
        for token in re.findall(r"`([a-z_]+\.[a-z_0-9]+)`", line):
            if token in readable or NOT_PARAMETER.search(token):
                continue
            what = "an unknown key" if token.split(".", 1)[0] in sections else "no section of the configuration"
            problems.append(f"{docs}:{number}: names `{token}`: {what}")
    for p in problems:
        print(p)
    if problems:
        print(f"check_config_docs: {len(problems)} problems")
        return 1
    print(f"check_config_docs: {len(readable)} keys, each documented and readable")
    return 0


if __name__ == "__main__":
    sys.exit(main())
