#!/usr/bin/env python3
"""The tables of docs/controllers.md from a batch folder of data/scenarios/controllers.yaml.

Usage: scripts/controllers_table.py DIR

Prints two Markdown tables from DIR/episodes.jsonl: per local controller and fault over all
worlds (successes, mean simulated time of the successes, and the navigation metrics pooled as
summary.csv pools them per row: the smallest minimum clearance, means of the episodes' mean
clearance, near share, RMS jerk and angular acceleration, the median of the episodes' median
compute times and the largest of their 99th percentiles; docs/batch.md), the successes per world
and controller, then every episode that did not succeed with its reason.
"""
import json
import statistics
import sys
from collections import defaultdict


def numbers(records, key):
    return [r[key] for r in records if isinstance(r.get(key), (int, float))]


def fmt(value, digits):
    return "-" if value is None else f"{value:.{digits}f}"


def lower_median(values):
    return sorted(values)[(len(values) - 1) // 2] if values else None


def row(controller, fault, records):
    ok = [r for r in records if r["succeeded"]]
    mean = lambda v: statistics.fmean(v) if v else None  # noqa: E731
    mins = numbers(records, "min_clearance_m")
    cells = [controller, fault, f"{len(ok)}/{len(records)}",
             fmt(mean([r["time_s"] for r in ok]), 1),
             fmt(min(mins) if mins else None, 3),
             fmt(mean(numbers(records, "mean_clearance_m")), 3),
             fmt(mean(numbers(records, "near_obstacle_share")), 3),
             fmt(mean(numbers(records, "rms_jerk_mps3")), 2),
             fmt(mean(numbers(records, "rms_angular_accel_radps2")), 2),
             fmt(lower_median(numbers(records, "controller_ms_median")), 4),
             fmt(max(numbers(records, "controller_ms_p99"), default=None), 4)]
    return "| " + " | ".join(cells) + " |"


def main(folder):
    with open(f"{folder}/episodes.jsonl") as f:
        records = [json.loads(line) for line in f if line.strip()]
    records.sort(key=lambda r: r["index"])  # the scenario's order, not the order they finished
    groups = defaultdict(list)
    for r in records:
        groups[(r["controller"], r["fault"])].append(r)
    print("| controller | fault | succeeded | mean time (s) | min clearance (m) | mean clearance (m) "
          "| share within 0.3 m | RMS jerk (m/s^3) | RMS angular accel. (rad/s^2) "
          "| controller median (ms) | controller p99, worst (ms) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for (controller, fault), group in groups.items():
        print(row(controller, fault, group))
    print()
    controllers = list(dict.fromkeys(r["controller"] for r in records))
    print("| world | " + " | ".join(controllers) + " |")
    print("|---|" + "---|" * len(controllers))
    by_world = defaultdict(list)
    for r in records:
        by_world[r["world"]].append(r)
    for world, group in by_world.items():
        cells = []
        for c in controllers:
            mine = [r for r in group if r["controller"] == c]
            cells.append(f"{sum(r['succeeded'] for r in mine)}/{len(mine)}")
        print(f"| {world} | " + " | ".join(cells) + " |")
    print()
    print("| episode | status | reason | at (s) |")
    print("|---|---|---|---|")
    for r in records:
        if not r["succeeded"]:
            at = r.get("failure_time_s")
            episode = r["id"].replace("|", "\\|")  # the id's separators, not table columns
            print(f"| {episode} | {r['status']} | {r.get('failure') or '-'} | {fmt(at, 1) if at is not None else '-'} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
