"""Race a controller written in Python against plantsim's own on the same seeds and faults, and
time both: the same physics, sensors and docking referee; only the path following differs.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/race.py [--seeds N] [--world FILE]
"""
import argparse
import time

import plantsim
from pursuit import make_pursuit


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--world", default="data/worlds/plants/substation_yard.json")
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--noisy", default="configs/noisy_sensing.json", help="a config with sensor noise")
    args = ap.parse_args()
    world = plantsim.load_world(args.world)
    controller = make_pursuit()
    totals = {}
    # "echo" hands plantsim's own command back from Python: the same trajectory, so its time over
    # plantsim's is the cost of calling Python at the control rate, nothing else.
    echo = lambda obs: obs.builtin  # noqa: E731
    for name, steer in (("plantsim", None), ("echo", echo), ("python", controller)):
        docked, driven, seconds, errors = 0, 0.0, 0.0, []
        for seed in range(1, args.seeds + 1):
            t0 = time.perf_counter()
            r = plantsim.run(world, seed=seed, config=args.noisy, controller=steer)
            seconds += time.perf_counter() - t0
            docked += r.docked
            driven += r.summary["time_s"]
            if r.docked:
                errors.append(r.summary["position_error_m"])
        totals[name] = seconds
        mean_err = 1000 * sum(errors) / len(errors) if errors else float("nan")
        print(f"{name:9s} docked {docked}/{args.seeds}, mean time to dock {driven / args.seeds:.1f} s, "
              f"mean position error {mean_err:.1f} mm, wall clock {seconds:.2f} s")
    print(f"a Python controller in the loop costs {totals['echo'] / totals['plantsim']:.2f} x the built-in "
          f"episode's time (echo: the same trajectories); this pursuit's episodes took "
          f"{totals['python'] / totals['plantsim']:.2f} x (different drives; measured in this run)")


if __name__ == "__main__":
    main()
