"""The Python module's bench: `python3 -m plantsim.bench [--quick]` prints one JSON line per
case, each with its baseline measured in the same run and the ratio (docs/python.md):

- vector_env: environment steps per second of VectorEnv(8) on every core with a linear numpy
  policy, against plantsim's own controller's control periods per second, the same world and
  seeds run by plantsim.run on the same cores (target: at least 20,000 steps per second);
- vector_env_beside_a_busy_core: VectorEnv(8) on two threads against one while another process
  keeps a core busy (target: two threads never slower, ratio at least 1.0);
- steered_run: an episode steered by a Python controller that returns None (plantsim's command)
  against the same episode with plantsim's own controller (target: at most 1.5 x its time);
- scan_read: reading Observation.scan_ranges against copying a numpy array of as many doubles
  (target: under 2 us a read).
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import threading
import time
import timeit

import numpy as np

import plantsim

WORLD = str(pathlib.Path(__file__).resolve().parents[3] / "data" / "worlds" / "examples" / "small_plant.json")


def _linear_policy(weights):
    def act(obs):
        to_go = obs["waypoint"] - obs["pose"][:, :2]
        yaw = obs["pose"][:, 2]
        c, s = np.cos(yaw), np.sin(yaw)
        ahead = np.stack([c * to_go[:, 0] + s * to_go[:, 1], c * to_go[:, 1] - s * to_go[:, 0]], axis=1)
        return np.clip(ahead @ weights, -1.0, 1.0)
    return act


def vector_env(world, steps, seeds):
    policy = _linear_policy(np.array([[0.6, 0.0], [0.0, 2.0]]))
    env = plantsim.VectorEnv(8, world)
    obs, _ = env.reset(seed=1)
    start = time.perf_counter()
    for _ in range(steps):
        obs, *_ = env.step(policy(obs))
    stepped = 8 * steps / (time.perf_counter() - start)
    # plantsim's own controller on the same cores: one thread per core, each running episodes.
    periods, lock = [0], threading.Lock()

    def run(chunk):
        for s in chunk:
            n = len(plantsim.run(world, seed=s, start="random").trajectory)
            with lock:
                periods[0] += n
    cores = os.cpu_count() or 1
    threads = [threading.Thread(target=run, args=(range(1 + i, seeds + 1, cores),)) for i in range(cores)]
    start = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    own = periods[0] / (time.perf_counter() - start)
    return {"case": "vector_env", "envs": 8, "steps_per_s": round(stepped), "baseline": "plantsim.run control periods per s",
            "baseline_per_s": round(own), "ratio": round(stepped / own, 3), "target_steps_per_s": 20000}


def _steps_per_s(world, steps, threads):
    policy = _linear_policy(np.array([[0.6, 0.0], [0.0, 2.0]]))
    env = plantsim.VectorEnv(8, world, threads=threads)
    obs, _ = env.reset(seed=1)
    start = time.perf_counter()
    for _ in range(steps):
        obs, *_ = env.step(policy(obs))
    return 8 * steps / (time.perf_counter() - start)


def vector_env_beside_a_busy_core(world, steps):
    """VectorEnv(8) on two threads against one, while another process keeps a core busy (a
    spinning Python): a helper thread the kernel leaves waiting must not hold the steps up."""
    busy = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        one, two = [], []
        for _ in range(3):  # alternated, so that a change in the machine's load meets both
            one.append(_steps_per_s(world, steps, 1))
            two.append(_steps_per_s(world, steps, 2))
    finally:
        busy.kill()
        busy.wait()
    one, two = sorted(one)[1], sorted(two)[1]
    return {"case": "vector_env_beside_a_busy_core", "envs": 8, "steps_per_s_two_threads": round(two),
            "baseline": "the same on one thread", "baseline_per_s": round(one), "ratio": round(two / one, 3),
            "target_ratio": 1.0}


def steered_run(world, seeds):
    def echo(observation):
        return None

    def total(controller):
        start = time.perf_counter()
        for s in range(1, seeds + 1):
            plantsim.run(world, seed=s, controller=controller)
        return time.perf_counter() - start
    own = min(total(None) for _ in range(2))
    steered = min(total(echo) for _ in range(2))
    return {"case": "steered_run", "seeds": seeds, "steered_s": round(steered, 3), "baseline": "plantsim's own controller",
            "baseline_s": round(own, 3), "ratio": round(steered / own, 3), "target_ratio": 1.5}


def scan_read(world):
    held = []
    plantsim.run(world, seed=1, controller=lambda o: held.append(o) if len(held) < 40 else None)
    o = held[-1]
    n = 20000
    read = min(timeit.repeat(lambda: o.scan_ranges, number=n, repeat=3)) / n
    copy_of = np.array(o.scan_ranges)
    copy = min(timeit.repeat(lambda: np.array(copy_of), number=n, repeat=3)) / n
    return {"case": "scan_read", "beams": int(copy_of.size), "read_us": round(read * 1e6, 3),
            "baseline": "numpy copy of as many doubles", "baseline_us": round(copy * 1e6, 3),
            "ratio": round(read / copy, 3), "target_us": 2.0}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer steps and seeds (a smoke run)")
    parser.add_argument("--world", default=WORLD)
    a = parser.parse_args(argv)
    steps, seeds = (100, 2) if a.quick else (2000, 8)
    cases = (lambda: vector_env(a.world, steps, seeds), lambda: vector_env_beside_a_busy_core(a.world, steps),
             lambda: steered_run(a.world, seeds), lambda: scan_read(a.world))
    for case in cases:
        print(json.dumps(case()), flush=True)


if __name__ == "__main__":
    main()
