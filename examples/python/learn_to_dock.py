"""A tiny learner on the step-wise environment: random search (a (1+1) hill climb) over a linear
policy that steers towards the plan's waypoint, tuned on some seeds and judged on others,
plotted with matplotlib into a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/learn_to_dock.py [--iterations N] [--out FILE.png]

The policy maps the waypoint 1 m ahead on plantsim's plan (ahead and across, in the robot's
frame, and the heading error to it) to (v, omega) through a 3 x 2 matrix, clipped to 1 m/s and
1 rad/s. It starts timid (0.05 m/s per metre ahead):
the robot crawls and runs out of its step budget before the staging pose, where plantsim's
docking manoeuvre would take over. Each iteration perturbs the matrix and keeps the perturbation
if the tuning seeds' score (docked episodes, then the mean return) improves. The held-out seeds
of its plant, and random starts on six generated plants of other styles it never saw, are run
once before and once after: their docking rates are the learner's result.
"""
import argparse

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import plantsim


def act(weights, obs):
    """(v, omega) = clip(features @ weights): the waypoint ahead and across in the robot's frame
    (m) and the heading error to it (rad)."""
    to_go = obs["waypoint"] - obs["pose"][:, :2]
    yaw = obs["pose"][:, 2]
    c, s = np.cos(yaw), np.sin(yaw)
    ahead, across = c * to_go[:, 0] + s * to_go[:, 1], c * to_go[:, 1] - s * to_go[:, 0]
    features = np.stack([ahead, across, np.arctan2(across, ahead)], axis=1)
    return np.clip(features @ weights, -1.0, 1.0)


def evaluate(env, weights, first_seed):
    """Each environment's first episode from seed first_seed + i: (docked count, mean return)."""
    obs, _ = env.reset(seed=first_seed)
    n = env.num_envs
    returns, finished, docked = np.zeros(n), np.zeros(n, bool), np.zeros(n, bool)
    while not finished.all():
        obs, reward, terminated, truncated, info = env.step(act(weights, obs))
        returns += np.where(finished, 0.0, reward)
        ended = (terminated | truncated) & ~finished
        docked |= ended & info["docked"]
        finished |= ended
    return int(docked.sum()), float(returns.mean())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--world", default="data/worlds/examples/small_plant.json")
    ap.add_argument("--iterations", type=int, default=25)
    ap.add_argument("--envs", type=int, default=8)
    ap.add_argument("--max-steps", type=int, default=1500, help="step budget per episode (50 s at 30 Hz)")
    ap.add_argument("--out", default="results/python_learn_to_dock.png")
    ap.add_argument("--held-out-starts", type=int, default=4,
                    help="random starts on each of six generated plants it never saw (0: none)")
    ap.add_argument("--held-out-max-steps", type=int, default=6000, help="their step budget (200 s)")
    args = ap.parse_args()
    env = plantsim.VectorEnv(args.envs, args.world, max_steps=args.max_steps)
    # Held out further: generated plants of six styles (100 x 60 m) no tuning saw, as a scenario
    # whose episodes the environments take one each (reset(seed=0): environment i, episode i).
    plants = None
    if args.held_out_starts > 0:
        styles = ["sparse", "dense", "racks", "corridors", "yard", "mixed"]
        scenario = {"worlds": [f"data/worlds/generated/styles/{s}_s6.json" for s in styles],
                    "seeds": args.held_out_starts, "starts": "random"}
        plants = plantsim.VectorEnv(len(styles) * args.held_out_starts, scenario=scenario,
                                    max_steps=args.held_out_max_steps)
    rng = np.random.default_rng(1)
    tune_seed, held_out_seed = 1, 1001  # tuning seeds 1..envs, held-out seeds 1001..1000+envs
    weights = np.array([[0.05, 0.0], [0.0, 0.0], [0.0, 0.5]])  # rows: ahead, across, heading error
    before = evaluate(env, weights, held_out_seed)
    plants_before = evaluate(plants, weights, 0) if plants else None
    best = evaluate(env, weights, tune_seed)
    history = [best]
    for k in range(args.iterations):
        candidate = weights + rng.normal(0.0, 0.15, weights.shape)
        score = evaluate(env, candidate, tune_seed)
        if score > best:
            weights, best = candidate, score
        history.append(best)
        print(f"iteration {k + 1:2d}: tuning docked {best[0]}/{args.envs}, mean return {best[1]:.2f}")
    after = evaluate(env, weights, held_out_seed)
    print(f"held-out seeds: docked {before[0]}/{args.envs} before, {after[0]}/{args.envs} after "
          f"(mean return {before[1]:.2f} -> {after[1]:.2f}); policy {weights.round(3).tolist()}")
    bars = [("seeds\nbefore", before, args.envs, "#999999"), ("seeds\nafter", after, args.envs, "#009E73")]
    if plants:
        plants_after = evaluate(plants, weights, 0)
        print(f"held-out generated plants (six styles, {plants.num_envs} starts): docked "
              f"{plants_before[0]}/{plants.num_envs} before, {plants_after[0]}/{plants.num_envs} after")
        bars += [("plants\nbefore", plants_before, plants.num_envs, "#999999"),
                 ("plants\nafter", plants_after, plants.num_envs, "#0072B2")]

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4), gridspec_kw={"width_ratios": [2, 1]})
    left.plot(range(len(history)), [h[0] / args.envs for h in history], color="#0072B2", marker="o",
              label="tuning seeds: docked fraction (best so far)")
    left.set_xlabel("iteration"), left.set_ylabel("docked fraction"), left.set_ylim(-0.05, 1.05)
    left.set_title("Random search on the tuning seeds"), left.legend(loc="lower right")
    right.bar([b[0] for b in bars], [b[1][0] / b[2] for b in bars], color=[b[3] for b in bars])
    for x, (_, (count, _), total, _) in enumerate(bars):
        right.text(x, count / total + 0.02, f"{count}/{total}", ha="center")
    right.set_ylim(0, 1.1), right.set_ylabel("docked fraction")
    right.set_title("Held out: its plant's seeds" + (", new plants" if plants else ""))
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"plot: {args.out}")


if __name__ == "__main__":
    main()
