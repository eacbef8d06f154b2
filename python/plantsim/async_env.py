"""plantsim.AsyncVectorEnv: n environments, each an Env in a worker process of its own, stepped
together (Gymnasium's AsyncVectorEnv; next-step autoreset as VectorEnv). Where VectorEnv steps its
environments on C++ threads inside one process, this one takes anything an Env takes, a Python
reward function included, and keeps each environment's failures in its own process. The workers
are started with "spawn" (a fresh interpreter: no thread of this process is copied); their
arguments are pickled (a World pickles as its file and contents, checked on the other side).

    envs = plantsim.AsyncVectorEnv(4, world="data/worlds/examples/small_plant.json")
    obs, info = envs.reset(seed=1)            # environment i: seed 1 + i
    obs, rewards, terminated, truncated, info = envs.step(actions)  # actions: shape (4, 2)
    envs.close()
"""
import multiprocessing

import numpy as np

from .env import Env, _spaces


def _worker(connection, kwargs):
    try:
        env = Env(**kwargs)
        connection.send(("ready", (env._env.limits, kwargs.get("action", "twist"))))
    except Exception as e:  # noqa: BLE001 - handed to the parent, which raises it
        connection.send(("error", e))
        return
    while True:
        command, argument = connection.recv()
        if command == "close":
            return
        try:
            if command == "reset":
                connection.send(("ok", env.reset(**argument)))
            elif command == "step":
                connection.send(("ok", env.step(argument)))
        except Exception as e:  # noqa: BLE001
            connection.send(("error", e))


def _stack_info(infos):
    """Env infos stacked as Gymnasium's vector environments give them: info[key] an array over
    the environments, info["_" + key] which have it."""
    n = len(infos)
    out = {}
    for key in dict.fromkeys(k for info in infos for k in info):
        have = np.array([key in info for info in infos])
        values = [info.get(key) for info in infos]
        sample = next(v for v in values if v is not None)
        if isinstance(sample, (bool, np.bool_)):
            array = np.array([bool(v) if v is not None else False for v in values])
        elif isinstance(sample, (int, np.integer)) and not isinstance(sample, bool):
            array = np.array([int(v) if v is not None else 0 for v in values], dtype=np.int64)
        elif isinstance(sample, (float, np.floating)):
            array = np.array([float(v) if v is not None else 0.0 for v in values])
        else:
            array = np.empty(n, dtype=object)
            for i, v in enumerate(values):
                array[i] = v if v is not None else ""
        out[key], out["_" + key] = array, have
    return out


class AsyncVectorEnv:
    """n Env, each in a worker process; the arguments are Env's (render_mode aside)."""

    metadata = {"render_modes": [], "autoreset_mode": "NextStep"}
    render_mode = None

    def __init__(self, n, **env_kwargs):
        if not isinstance(n, int) or isinstance(n, bool) or not 1 <= n <= 256:
            raise ValueError(f"n must be a whole number from 1 to 256, got {n!r}")
        self.num_envs = n
        context = multiprocessing.get_context("spawn")
        self._connections, self._processes = [], []
        for _ in range(n):
            mine, theirs = context.Pipe()
            process = context.Process(target=_worker, args=(theirs, env_kwargs), daemon=True)
            process.start()
            theirs.close()
            self._connections.append(mine)
            self._processes.append(process)
        try:
            limits, action = self._gather()[0]
        except BaseException:
            self.close()
            raise
        self.single_action_space, self.single_observation_space = _spaces(
            limits, action, finite=bool(env_kwargs.get("finite", False)))
        self.action_space, self.observation_space = _spaces(limits, action, n,
                                                            finite=bool(env_kwargs.get("finite", False)))
        self._done = np.zeros(n, dtype=bool)

    def _gather(self):
        answers, failure = [], None
        for i, connection in enumerate(self._connections):
            kind, value = connection.recv()
            if kind == "error" and failure is None:
                failure = (i, value)
            answers.append(value)
        if failure is not None:
            i, e = failure
            raise type(e)(f"AsyncVectorEnv environment {i}: {e}") from e
        return answers

    def reset(self, *, seed=None, options=None):
        """seed None, s (environment i: s + i) or one per environment; options as Env's, or a list
        of one per environment."""
        seeds = [None] * self.num_envs if seed is None else (
            list(seed) if isinstance(seed, (list, tuple, np.ndarray)) else [seed + i for i in range(self.num_envs)])
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed: {self.num_envs} seeds (one per environment) expected, got {len(seeds)}")
        each = options if isinstance(options, (list, tuple)) else [options] * self.num_envs
        for connection, s, o in zip(self._connections, seeds, each):
            connection.send(("reset", {"seed": None if s is None else int(s), "options": o}))
        results = self._gather()
        self._done[:] = False
        return self._stack([r[0] for r in results]), _stack_info([r[1] for r in results])

    def step(self, actions):
        actions = np.asarray(actions)
        if actions.shape[0] != self.num_envs:
            raise ValueError(f"actions: one row per environment ({self.num_envs}) expected, got shape {actions.shape}")
        # Next-step autoreset: an environment that ended at the last step starts its next episode
        # now (a reset without a seed: its stream's next), with reward 0.
        for i, connection in enumerate(self._connections):
            connection.send(("reset", {}) if self._done[i] else ("step", actions[i]))
        results = self._gather()
        obs, infos = [], []
        rewards = np.zeros(self.num_envs)
        terminated = np.zeros(self.num_envs, dtype=bool)
        truncated = np.zeros(self.num_envs, dtype=bool)
        for i, r in enumerate(results):
            if self._done[i]:
                obs.append(r[0])
                infos.append(r[1])
            else:
                o, rewards[i], terminated[i], truncated[i], info = r
                obs.append(o)
                infos.append(info)
        self._done = terminated | truncated
        return self._stack(obs), rewards, terminated, truncated, _stack_info(infos)

    @staticmethod
    def _stack(observations):
        return {k: np.stack([o[k] for o in observations]) for k in observations[0]}

    def close(self):
        for connection in self._connections:
            try:
                connection.send(("close", None))
            except (BrokenPipeError, OSError):
                pass
        for process in self._processes:
            process.join(timeout=5)
            if process.is_alive():
                process.kill()
        self._connections, self._processes = [], []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        if getattr(self, "_processes", None):
            self.close()
