"""An episode followed step by step: a controller that lets plantsim drive (returns None) but
records what the robot perceived at every control period, then the record inspected beside the
trajectory: the estimate's uncertainty over time, the scan's returns, the truth kept apart.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/inspect_episode.py [--world FILE] [--seed N]
"""
import argparse

import numpy as np

import plantsim


class Recorder:
    """Called at the control rate with the observation; keeps what it wants, commands nothing."""

    def __init__(self):
        self.rows = []

    def __call__(self, obs):
        returns = np.isfinite(obs.scan_ranges) & (obs.scan_ranges < obs.scan_max_range)
        self.rows.append((obs.time, *obs.pose, np.sqrt(np.trace(obs.covariance[:2, :2])), int(returns.sum()),
                          len(obs.obstacles)))
        return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--world", default="data/worlds/examples/corridor_crossing.json")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rec = Recorder()
    r = plantsim.run(args.world, seed=args.seed, controller=rec, controller_name="recorder")
    seen = np.array(rec.rows)
    truth = r.trajectory[:, [r.columns.index(c) for c in ("t_s", "x_m", "y_m")]]
    # Match each observation to the trajectory row of its time (both at the control rate).
    rows = np.searchsorted(truth[:, 0], seen[:, 0] - 1e-9)
    error = np.hypot(seen[:, 1] - truth[rows, 1], seen[:, 2] - truth[rows, 2])
    print(f"{r.summary['world']}: {r.status}; {len(seen)} observations from t = {seen[0, 0]:.2f} s to {seen[-1, 0]:.2f} s")
    print(f"position sigma: median {1000 * np.median(seen[:, 4]):.1f} mm, max {1000 * seen[:, 4].max():.1f} mm")
    print(f"true position error (truth only here, after the run): median {1000 * np.median(error):.1f} mm, "
          f"max {1000 * error.max():.1f} mm")
    print(f"lidar returns per scan: median {np.median(seen[:, 5]):.0f}; most tracked obstacles at once: {int(seen[:, 6].max())}")
    print(f"summary: time {r.summary['time_s']:.1f} s, localisation {r.summary['localization_status']}, "
          f"steered_by {r.summary['steered_by']}")


if __name__ == "__main__":
    main()
