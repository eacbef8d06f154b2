"""Issue 85 (hardening IV), the Python module: episodes that cannot start, actions checked before
any environment steps, a World's pickle keeping its name, the error types of bad arguments, and
files written and read with '.' decimals under a comma locale. Cases that once killed Python run
in a subprocess, so that a crash fails the test instead of the test run."""
import json
import locale
import math
import os
import pickle
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import plantsim
from test_threads_and_signals import MODULE_PATH

WORLD = "data/worlds/examples/small_plant.json"


def python(script, timeout=120):
    env = dict(os.environ, PYTHONPATH=MODULE_PATH)
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], env=env, capture_output=True,
                          text=True, timeout=timeout)


def walled_world(source, tmp_path):
    """The corridor with a wall across it: no path from the start to the charger."""
    world = json.loads((source / "data/worlds/examples/corridor_crossing.json").read_text())
    world.pop("moving_obstacles", None)
    world["name"] = "walled"
    world["obstacles"] = [[9.8, 0.0, 10.2, 3.0]]
    path = tmp_path / "walled.json"
    path.write_text(json.dumps(world))
    return path


# 1. An episode whose plan fails at its start: a clear InputError from reset, never a crash.

def unstartable(source, tmp_path):
    return [(walled_world(source, tmp_path), "vg"), (source / WORLD, "maze-left"),
            (source / "data/worlds/plants/cable_tunnel_maze.json", "gcr")]


@pytest.mark.parametrize("case", [0, 1, 2])
def test_an_episode_that_cannot_start_raises_and_the_env_stays_usable(source, tmp_path, case):
    world, planner = unstartable(source, tmp_path)[case]
    assert plantsim.run(world, planner=planner).summary["status"] != "docked"  # run() says why
    out = python(f"""
        import plantsim
        for make in (lambda: plantsim.Env({str(world)!r}, planner={planner!r}, start="world"),
                     lambda: plantsim.VectorEnv(2, {str(world)!r}, planner={planner!r}, start="world")):
            env = make()
            for seed in (1, 2):
                try:
                    env.reset(seed=seed)
                    print("reset returned")
                except plantsim.InputError as e:
                    print("InputError", {planner!r} in str(e) and "before the agent's first step" in str(e))
            try:
                env.step(env.action_space.sample())
                print("stepped")
            except plantsim.InputError as e:
                print("InputError", "reset()" in str(e))
    """)
    assert out.returncode == 0, (out.returncode, out.stderr[-2000:])
    assert out.stdout.split("\n")[:6] == ["InputError True"] * 6, out.stdout


def test_after_a_failed_reset_a_startable_episode_still_runs(source, tmp_path):
    # One world, two starts: from inside the walled-off half the plan fails; from the charger's
    # side it does not. The same Env object carries on after the failure.
    world = walled_world(source, tmp_path)
    env = plantsim.Env(world, start="world")
    with pytest.raises(plantsim.InputError, match="walled"):
        env.reset(seed=1)
    good = plantsim.Env(world, start=[15.0, 1.5, 0.0])
    obs, info = good.reset(seed=1)
    assert obs["time"] >= 1.0 and good.step((0.2, 0.0))[0]["time"] > obs["time"]
    with pytest.raises(plantsim.InputError, match="reset"):
        env.step((0.0, 0.0))


# 5. Actions: every one checked before any environment steps; the type and the index named.

def test_a_bad_action_in_a_vector_step_steps_no_environment(source):
    env = plantsim.VectorEnv(3, source / WORLD, threads=1)
    obs, _ = env.reset(seed=1)
    t0 = obs["time"].copy()
    bad = np.zeros((3, 2))
    bad[2, 1] = np.nan
    with pytest.raises(plantsim.InputError, match=r"actions\[2, 1\] is nan"):
        env.step(bad)
    obs, *_ = env.step(np.zeros((3, 2)))
    # One period each since the reset: the refused call stepped none (environment 0 and 1 did).
    assert np.allclose(obs["time"] - t0, obs["time"][0] - t0[0]) and (obs["time"] - t0)[0] < 0.05


@pytest.mark.parametrize("actions, error, match", [
    (np.zeros((2, 1)), plantsim.InputError, r"shape \(3, 2\).*got shape \(2, 1\)"),
    (np.zeros((3, 2, 1)), plantsim.InputError, r"got shape \(3, 2, 1\)"),
    (np.zeros((3, 2), dtype=complex), TypeError, "complex"),
    (np.full((3, 2), "0.1"), TypeError, "text"),
    (np.full((3, 2), None, dtype=object), TypeError, "object"),
    (np.ones((3, 2), dtype=bool), TypeError, "bool"),
    ([[0.1, 0.0], [0.1], [0.0, 0.0]], TypeError, "actions"),
])
def test_vector_actions_of_the_wrong_shape_or_kind_are_refused(source, actions, error, match):
    env = plantsim.VectorEnv(3, source / WORLD, threads=1)
    env.reset(seed=1)
    with pytest.raises(error, match=match):
        env.step(actions)
    assert isinstance(env.step(np.zeros((3, 2)))[1], np.ndarray)  # still usable


@pytest.mark.parametrize("action, error, match", [
    (complex(0.1, 0.2), TypeError, "complex"),
    ((0.1 + 1j, 0.0), TypeError, "complex"),
    ([[0.1, 0.0]], plantsim.InputError, r"got shape \(1, 2\)"),
    ((0.1, 0.0, 0.0), plantsim.InputError, r"got shape \(3,\)"),
    ((True, False), TypeError, "bool"),
    (("0.1", "0"), TypeError, "text"),
    ((0.1, math.inf), plantsim.InputError, r"action\[1\] is inf"),
])
def test_one_envs_bad_actions_are_refused(source, action, error, match):
    env = plantsim.Env(source / WORLD)
    env.reset(seed=1)
    with pytest.raises(error, match=match):
        env.step(action)
    env.step((0.1, 0.0))


# 6. A World's pickle keeps what was changed after loading.

def test_a_renamed_world_pickles_with_its_new_name(source):
    world = plantsim.load_world(source / WORLD)
    world.name = "renamed plant"
    again = pickle.loads(pickle.dumps(world))
    assert again.name == "renamed plant"
    assert np.array_equal(again.obstacles, world.obstacles)
    assert plantsim.load_world(source / WORLD).name == "small_plant"  # the loaded one unchanged
    with pytest.raises(plantsim.InputError, match="name"):
        world.name = "a|b"


# 7. Errors: the fitting Python type, naming the argument.

def test_bad_arguments_raise_fitting_types_naming_the_argument(source, tmp_path):
    world = source / WORLD
    with pytest.raises(FileNotFoundError, match="nowhere.json"):
        plantsim.load_world(tmp_path / "nowhere.json")
    with pytest.raises(FileNotFoundError):
        plantsim.Env(tmp_path / "nowhere.json")
    with pytest.raises(FileNotFoundError):
        plantsim.nav2_import(tmp_path / "nowhere.yaml")
    with pytest.raises(FileNotFoundError):
        plantsim.run(world, config=tmp_path / "nowhere.json")
    with pytest.raises(TypeError, match="world"):
        plantsim.run(123)
    with pytest.raises(TypeError, match="config"):
        plantsim.run(world, config=42)
    with pytest.raises(TypeError, match="seed"):
        plantsim.run(world, seed=1.5)
    for seed in (-1, 2**64):
        with pytest.raises(plantsim.InputError, match="seed"):
            plantsim.run(world, seed=seed)
    with pytest.raises(plantsim.InputError, match="yaw"):
        plantsim.run(world, start=(1.0, 1.0, 1e39))
    with pytest.raises(plantsim.InputError, match="yaw"):
        plantsim.load_world(world, start=(1.0, 1.0, 101.0))
    with pytest.raises(plantsim.InputError, match="finite"):
        plantsim.Env(world, start=[float("nan"), 1.0, 0.0])
    with pytest.raises(plantsim.InputError, match="max_steps"):
        plantsim.Env(world, max_steps=-5)
    with pytest.raises(plantsim.InputError, match="n must"):
        plantsim.VectorEnv(-1, world)
    with pytest.raises(plantsim.InputError, match="threads"):
        plantsim.VectorEnv(2, world, threads=-1)
    with pytest.raises(plantsim.InputError, match="threads"):
        plantsim.VectorEnv(2, world, threads=10**6)
    env = plantsim.Env(world)
    with pytest.raises(plantsim.InputError, match="seed"):
        env.reset(seed=-1)
    with pytest.raises(TypeError, match="options"):
        env.reset(options=[1])
    scenario = {"name": "args", "worlds": [str(world)], "seeds": 1}
    with pytest.raises(plantsim.InputError, match="threads"):
        plantsim.batch(scenario, tmp_path / "b", threads=-3, figures=False)
    with pytest.raises(plantsim.InputError, match="seed"):
        plantsim.tune(_tune_scenario(source, tmp_path), tmp_path / "t", seed=-1)


def _tune_scenario(source, tmp_path):
    path = tmp_path / "t.yaml"
    path.write_text(json.dumps({"name": "tiny", "worlds": [str(source / WORLD)], "seeds": 1,
                                "tune": {"validation_seeds": [101]}}))
    return path


def test_a_files_field_error_is_an_input_error_naming_file_and_field(source, tmp_path):
    world = json.loads((source / WORLD).read_text())
    world["robot"]["max_speed_mps"] = -1
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(world))
    with pytest.raises(plantsim.InputError) as e:
        plantsim.load_world(path)
    assert isinstance(e.value, ValueError)
    assert e.value.file == str(path) and e.value.field == "robot.max_speed_mps"
    assert "robot.max_speed_mps" in str(e.value)
    with pytest.raises(plantsim.InputError) as plain:
        plantsim.run(source / WORLD, planner="nope")
    assert plain.value.file is None and plain.value.field is None


# 8. A comma-decimal locale in the host process: files still written and read with '.'.

COMMA_LOCALES = ("de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8")


def comma_locale():
    was = locale.setlocale(locale.LC_ALL)
    try:
        for name in COMMA_LOCALES:
            try:
                locale.setlocale(locale.LC_ALL, name)
                return name
            except locale.Error:
                pass
        return None
    finally:
        locale.setlocale(locale.LC_ALL, was)


def test_a_comma_locale_changes_no_file(source, tmp_path):
    name = comma_locale()
    if name is None:
        pytest.skip("no comma-decimal locale installed (apt-get install locales; generate de_DE.UTF-8)")
    world = str(source / "data/worlds/examples/corridor_crossing.json")
    out = python(f"""
        import json, locale, plantsim
        locale.setlocale(locale.LC_ALL, {name!r})
        assert locale.localeconv()["decimal_point"] == ","
        run = plantsim.run({world!r}, out={str(tmp_path / 'run')!r})
        b = plantsim.batch({{"name": "comma", "worlds": [{world!r}], "seeds": 2}}, {str(tmp_path / 'b')!r},
                           figures=False)
        print(json.dumps([row["success_rate"] for row in b["rows"]]))
        plantsim.tune({str(_tune_scenario(source, tmp_path))!r}, {str(tmp_path / 't')!r},
                      params=["tracking.max_linear_speed_mps=0.3:0.8"], budget=1, figures=False)
        print("done")
    """, timeout=600)
    assert out.returncode == 0, out.stderr[-3000:]
    assert out.stdout.split()[-1] == "done", out.stdout
    rates = json.loads(out.stdout.split("\n")[0])
    assert rates and all(isinstance(r, float) and 0 <= r <= 1 for r in rates)
    rows = (tmp_path / "run/trajectory.csv").read_text().splitlines()
    assert all(len(row.split(",")) == 15 for row in rows)
    float(rows[1].split(",")[1])
    for csv in (tmp_path / "b/summary.csv", tmp_path / "t/validation.csv"):
        header, *lines = csv.read_text().splitlines()
        assert lines and all(len(line.split(",")) == len(header.split(",")) for line in lines), csv
