"""plantsim.Env and plantsim.VectorEnv: an episode driven one control period at a time, with the
Gymnasium API's contract (https://gymnasium.farama.org/api/env/; the package itself is not
needed: these classes follow its published semantics and spaces' fields).

    env = plantsim.Env("data/worlds/examples/small_plant.json")
    obs, info = env.reset(seed=3)
    while True:
        obs, reward, terminated, truncated, info = env.step(policy(obs))
        if terminated or truncated:
            break

An observation is the robot's perception as numpy arrays (never the simulator's truth): "scan"
(ranges of the newest lidar scan, NaN for a dropout), "scan_time" (when that scan was taken: the
same value twice is the same scan), "pose" (the estimate [x, y, yaw], map frame), "covariance"
(3 x 3), "velocity" ([encoder speed m/s, gyro yaw rate rad/s]), "odometry" (dead-reckoned
[x, y, yaw]), "staging" (where docking takes over), "waypoint" (the point 1 m along plantsim's
plan ahead of the estimate), "charger" (the docked pose as the detector saw it, robot frame;
NaN when unseen) and "charger_seen", "phase" (index in plantsim.PHASES), "health" (0 ok,
1 degraded, 2 lost), "time" (s). docs/python.md has the reward, the spaces and an example.
"""
import json
import os
import tempfile

import numpy as np

from ._plantsim import PHASES, _Env, _VectorEnv


def _absolute_worlds(scenario):
    """A scenario dict's relative world paths made absolute from the working folder."""
    scenario = dict(scenario)
    worlds = scenario.get("worlds")
    if isinstance(worlds, list):
        scenario["worlds"] = [os.path.abspath(w) if isinstance(w, str) and not w.startswith("$data/") else w
                              for w in worlds]
    return scenario


def _with_scenario(scenario, make):
    """make(scenario as a path): a dict (the keys of docs/batch.md) is written to a scratch file
    for the loader to read, its relative world paths taken from the working folder."""
    if not isinstance(scenario, dict):
        return make(scenario)
    with tempfile.TemporaryDirectory(prefix="plantsim_env_") as scratch:
        path = os.path.join(scratch, "scenario.yaml")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(_absolute_worlds(scenario), f)  # JSON is YAML
        return make(path)


class Box:
    """Arrays within bounds, with the fields of Gymnasium's spaces.Box (low, high, shape, dtype)
    and its sample() and contains(). sample() draws as Gymnasium's does: reals uniformly within
    finite bounds (a normal draw on an infinite side, shifted past a finite one), whole numbers
    uniformly from low to high inclusive, booleans as fair coins. contains() takes an array of
    the space's shape whose dtype casts to the space's (a float for an int space does not), within
    the bounds; NaN is contained in a real space, where plantsim marks "none" with it (a lidar
    dropout, an unseen charger) - a departure from Gymnasium, whose Box refuses NaN - unless
    nan=False (the spaces of finite observations, Env(finite=True))."""

    def __init__(self, low, high, shape=None, dtype=np.float64, seed=None, nan=True):
        shape = tuple(shape) if shape is not None else np.shape(low)
        self.nan = bool(nan)  # whether NaN ("none") is contained (real spaces; False: Gymnasium's rule)
        self.low = np.broadcast_to(np.asarray(low, dtype=dtype), shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=dtype), shape).copy()
        self.shape, self.dtype = shape, np.dtype(dtype)
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        if self.dtype == np.bool_:
            return np.asarray(self._rng.integers(0, 2, size=self.shape), dtype=np.bool_)
        if np.issubdtype(self.dtype, np.integer):
            return np.asarray(self._rng.integers(self.low, self.high, size=self.shape, endpoint=True),
                              dtype=self.dtype)
        low, high = np.asarray(self.low, np.float64), np.asarray(self.high, np.float64)
        bounded_low, bounded_high = np.isfinite(low), np.isfinite(high)
        normal = self._rng.normal(size=self.shape)
        uniform = self._rng.uniform(np.where(bounded_low, low, 0.0), np.where(bounded_high, high, 0.0),
                                    size=self.shape)
        exponential = self._rng.exponential(size=self.shape)
        value = np.where(bounded_low & bounded_high, uniform,
                         np.where(bounded_low, low + exponential,
                                  np.where(bounded_high, high - exponential, normal)))
        return np.asarray(value, dtype=self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        if x.shape != self.shape or not np.can_cast(x.dtype, self.dtype, casting="same_kind"):
            return False
        if self.dtype == np.bool_:
            return x.dtype == np.bool_
        if np.issubdtype(self.dtype, np.integer) and not np.issubdtype(x.dtype, np.integer):
            return False
        inside = (x >= self.low) & (x <= self.high)
        if np.issubdtype(self.dtype, np.floating) and self.nan:
            inside |= np.isnan(x)
        return bool(np.all(inside))

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


class Dict:
    """Named spaces, as Gymnasium's spaces.Dict (a mapping of its spaces)."""

    def __init__(self, spaces):
        self.spaces = dict(spaces)

    def __getitem__(self, key):
        return self.spaces[key]

    def __iter__(self):
        return iter(self.spaces)

    def __len__(self):
        return len(self.spaces)

    def keys(self):
        return self.spaces.keys()

    def items(self):
        return self.spaces.items()

    def values(self):
        return self.spaces.values()

    def seed(self, seed=None):
        seeds = np.random.SeedSequence(seed).spawn(len(self.spaces))
        for s, child in zip(self.spaces.values(), seeds):
            s.seed(int(child.generate_state(1)[0]))
        return [seed]

    def sample(self):
        return {k: s.sample() for k, s in self.spaces.items()}

    def contains(self, x):
        return isinstance(x, dict) and x.keys() == self.spaces.keys() and all(
            s.contains(x[k]) for k, s in self.spaces.items())

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return "Dict(" + ", ".join(f"{k}: {s!r}" for k, s in self.spaces.items()) + ")"


def _spaces(limits, action, n=None, finite=False):
    max_speed, wheel_base, beams, max_range = limits
    lead = () if n is None else (n,)
    inf = np.inf
    if action == "wheels":
        act = Box(-max_speed, max_speed, lead + (2,))
    else:
        turn = 2.0 * max_speed / wheel_base
        act = Box(np.broadcast_to([-max_speed, -turn], lead + (2,)), np.broadcast_to([max_speed, turn], lead + (2,)))
    box = lambda low, high, shape, dtype=np.float64: Box(low, high, lead + shape, dtype, nan=not finite)
    fields = {
        "scan": box(0.0, max_range if np.isfinite(max_range) else inf, (beams,)),
        "scan_time": box(0.0, inf, ()),
        "pose": box(-inf, inf, (3,)),
        "covariance": box(-inf, inf, (3, 3)),
        "velocity": box(-inf, inf, (2,)),
        "odometry": box(-inf, inf, (3,)),
        "staging": box(-inf, inf, (3,)),
        "waypoint": box(-inf, inf, (2,)),
        "charger": box(-inf, inf, (3,)),
        "charger_seen": box(0, 1, (), np.bool_),
        "phase": box(0, len(PHASES) - 1, (), np.int64),
        "health": box(0, 2, (), np.int64),
        "time": box(0.0, inf, ()),
    }
    if finite:  # what NaN marked, said by masks
        fields["scan_valid"] = box(0, 1, (beams,), np.bool_)
        fields["scan_seen"] = box(0, 1, (), np.bool_)
    return act, Dict(fields)


def _finite(obs, max_range):
    """obs with NaN replaced and masks added (Env(finite=True)): a dropout's range reads as the
    lidar's maximum (no return within reach) and scan_valid is False there; before the first
    scan, scan_time reads 0 and scan_seen is False; an unseen charger reads (0, 0, 0) beside
    charger_seen. Works on one observation and on a VectorEnv's stacked ones."""
    scan = obs["scan"]
    valid = ~np.isnan(scan)
    obs["scan"] = np.where(valid, scan, max_range)
    obs["scan_valid"] = valid
    seen = ~np.isnan(obs["scan_time"])
    obs["scan_time"] = np.where(seen, obs["scan_time"], 0.0)
    obs["scan_seen"] = np.asarray(seen)
    obs["charger"] = np.where(np.isnan(obs["charger"]), 0.0, obs["charger"])
    for key, value in obs.items():  # any other "none" (none expected) would break the promise
        if np.issubdtype(np.asarray(value).dtype, np.floating) and np.isnan(value).any():
            obs[key] = np.nan_to_num(value, nan=0.0)
    return obs


class Env:
    """One environment (Gymnasium's Env contract).

    world: a World or a world file's path; or scenario: a scenario file, or a dict with its keys
    (docs/batch.md; relative world paths from the working folder): its worlds, starts, faults
    and controllers' configs, reset(seed=s) its episode at index s mod their count, a seedless
    reset a drawn one (worlds and faults drawn per reset: domain randomisation).
    config: a dict or config file (docs/config.md) for a world. planner: a name from planners().
    start: "random" (the start a batch draws for the seed; the default), "world" or [x, y, yaw].
    docking: "plantsim" (its manoeuvre docks once the staging pose is reached, a control period
    a step, the action ignored: info["action_used"] says so), "plantsim-whole" (it docks to the
    end within the step that reaches the staging pose) or "agent" (the actions steer docking too).
    contact: "terminate" (the first contact with anything ends the episode: terminated, status
    "collision") or "continue" (the episode goes on; success still needs none).
    action: "twist" ((v m/s, omega rad/s), the default) or "wheels" ((left, right) m/s).
    reward: None for the default (docs/python.md), or f(obs, info) -> float.
    reward_weights: the default reward's weights by name over their defaults (progress 1,
    per_step 0.01, bumper 1, docked 10, failed 10).
    max_steps: truncate after this many steps (0: only the config's timeout_s truncates).
    render_mode: None or "rgb_array" (render() returns the plant now as an RGB array of
    render_size (width, height) pixels).
    finite: False (the default: NaN marks a lidar dropout, a scan not yet taken, an unseen
    charger) or True (finite values with masks: "scan_valid", "scan_seen", and "charger_seen"
    as always; the spaces then refuse NaN, as Gymnasium's do).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 15}
    spec = None

    def __init__(self, world=None, *, scenario=None, config=None, planner="vg", start="random",
                 docking="plantsim", contact="terminate", action="twist", reward=None, max_steps=0,
                 finite=False, reward_weights=None, render_mode=None, render_size=(960, 600)):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or \"rgb_array\", got {render_mode!r}")
        self.render_mode, self._render_size = render_mode, tuple(render_size)
        self._finite_range = None  # the lidar's maximum when finite (set below, before any step)
        if finite and reward is not None:  # the reward sees the observation the agent sees
            given = reward
            reward = lambda obs, info: given(_finite(obs, self._finite_range), info)
        self._env = _with_scenario(scenario, lambda s: _Env(world, s, config, planner, start, docking, contact,
                                                             action, reward, max_steps, reward_weights))
        if finite:
            self._finite_range = float(self._env.limits[3])
        self.action_space, self.observation_space = _spaces(self._env.limits, action, finite=finite)
        self.np_random = np.random.default_rng()

    def reset(self, *, seed=None, options=None):
        """A new episode. seed: the episode's seed (noise, and with start="random" its start; for
        a scenario, its episode at index seed mod the episode count), which also restarts the
        environment's stream of seeds; None: the stream's next seed, as Gymnasium's np_random
        continues (from the machine's entropy when no reset had a seed), so that resets without
        a seed never replay an episode. options: {"episode": id} for a scenario's episode by its
        id. Returns (obs, info)."""
        obs, info = self._env.reset(seed, options)  # checks the seed first (InputError naming it)
        if seed is not None:
            self.np_random = np.random.default_rng(seed)
            self.action_space.seed(seed)
        return self._observed(obs), info

    def _observed(self, obs):
        return obs if self._finite_range is None else _finite(obs, self._finite_range)

    def step(self, action):
        """Drives one control period with `action`; returns (obs, reward, terminated, truncated,
        info). terminated: docked or failed (a first contact too, unless contact="continue");
        truncated: the time ran out, the config's timeout_s or max_steps (info["truncated_by"]),
        with no terminal reward. Either way info has "status", "docked", "failure" and
        "collisions". Stepping after either raises InputError."""
        obs, reward, terminated, truncated, info = self._env.step(action)
        return self._observed(obs), reward, terminated, truncated, info

    def render(self):
        """With render_mode="rgb_array": the plant now as a (height, width, 3) uint8 array (the
        robot where it is, the path it drove by speed, plantsim's plan, the newest scan placed at
        the estimate, a legend and the clock), drawn as plantsim's figures are; else None."""
        if self.render_mode != "rgb_array":
            return None
        width, height = self._render_size
        return self._env.frame(width, height)

    def close(self):
        pass

    @property
    def unwrapped(self):
        return self

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


class VectorEnv:
    """n environments stepped together in C++ threads (Gymnasium's vector API, next-step
    autoreset: an environment that terminated or truncated at a step starts its next episode at
    the following step, which returns its first observation with reward 0).

    Environment i is an Env: reset(seed=s) gives it seed s + i (reset(seed=[s0, s1, ...]) the
    i-th), reset() and each autoreset the next seed of its own stream (Env.reset), so that no
    episode repeats unless asked.
    Observations are the Env's, stacked: obs["scan"] has shape (n, beams), obs["pose"] (n, 3).
    step(actions) takes an array of shape (n, 2). threads: 0 for one per core. info holds Env's
    keys stacked as Gymnasium's vector environments give them: info[key] an array over the
    environments and info["_" + key] which have it (how an episode ended: those that ended at
    this step). reward: None (the default reward, computed in C++) or f(obs, info) on the
    stacked observation and info, returning n numbers. The other arguments are Env's.
    """

    metadata = {"render_modes": [], "autoreset_mode": "NextStep"}
    render_mode = None

    def __init__(self, n, world=None, *, scenario=None, config=None, planner="vg", start="random",
                 docking="plantsim", contact="terminate", action="twist", max_steps=0, threads=0,
                 finite=False, reward=None, reward_weights=None):
        if reward is not None and not callable(reward):
            raise TypeError("reward must be callable: f(obs, info) -> one number per environment, or None")
        self._reward = reward
        self.num_envs = n
        self._env = _with_scenario(scenario, lambda s: _VectorEnv(n, world, s, config, planner, start, docking,
                                                                   contact, action, max_steps, threads,
                                                                   reward_weights))  # checks n first
        self._autoresetting = np.zeros(n, dtype=bool)
        self._finite_range = float(self._env.limits[3]) if finite else None
        self.single_action_space, self.single_observation_space = _spaces(self._env.limits, action, finite=finite)
        self.action_space, self.observation_space = _spaces(self._env.limits, action, n, finite=finite)

    def reset(self, *, seed=None, options=None):
        """New episodes in every environment: seed None, s (s + i for environment i) or one per
        environment; options {"episode": [id or None, ...]} (a scenario's episodes by id)."""
        obs, info = self._env.reset(seed, options)
        self._autoresetting = np.zeros(self.num_envs, dtype=bool)
        return self._observed(obs), info

    def step(self, actions):
        # Passed as given: the C++ side refuses complex, bool, text and object elements before
        # any environment steps (a cast to float64 here made 1+2j a 1 and "0.5" a 0.5).
        obs, rewards, terminated, truncated, info = self._env.step(actions)
        obs = self._observed(obs)
        if self._reward is not None:  # an environment starting its next episode gets 0
            given = np.asarray(self._reward(obs, info), dtype=np.float64)
            if given.shape != (self.num_envs,):
                raise ValueError(f"reward must return one number per environment, shape ({self.num_envs},), "
                                 f"got shape {given.shape}")
            rewards = np.where(self._autoresetting, 0.0, given)
        self._autoresetting = np.asarray(terminated) | np.asarray(truncated)
        return obs, rewards, terminated, truncated, info

    def _observed(self, obs):
        return obs if self._finite_range is None else _finite(obs, self._finite_range)

    def close(self):
        pass
