"""A parameter sweep designed in Python: plantsim's top speed against docking success and time,
over seeds, plotted with matplotlib into a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep.py [--seeds N] [--out FILE.png]
"""
import argparse

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import plantsim


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--world", default="data/worlds/plants/desulfurization_plant.json")
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--speeds", default="0.3,0.45,0.6,0.75")
    ap.add_argument("--out", default="results/python_sweep.png")
    args = ap.parse_args()
    world = plantsim.load_world(args.world)
    speeds = [float(s) for s in args.speeds.split(",")]
    success, times = [], []
    for v in speeds:
        runs = [plantsim.run(world, seed=s, config={"tracking": {"max_linear_speed_mps": v}})
                for s in range(1, args.seeds + 1)]
        success.append(np.mean([r.docked for r in runs]))
        times.append([r.summary["time_s"] for r in runs if r.docked])
        print(f"max_linear_speed_mps {v:.2f}: docked {sum(r.docked for r in runs)}/{len(runs)}, "
              f"median time {np.median(times[-1]) if times[-1] else float('nan'):.1f} s")
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot(speeds, [100 * s for s in success], "o-", color="tab:green")
    a.set(xlabel="tracking.max_linear_speed_mps (m/s)", ylabel="docked (%)", ylim=(0, 105),
          title=f"{world.name}: success, {args.seeds} seeds each")
    b.boxplot([t if t else [np.nan] for t in times], labels=[f"{v:.2f}" for v in speeds])
    b.set(xlabel="tracking.max_linear_speed_mps (m/s)", ylabel="time to dock (s)", title="time to dock (docked episodes)")
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
