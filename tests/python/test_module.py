"""The Python module against the command line and known answers: worlds of every format, plans
of known optimal length, runs equal to `plantsim run`, a controller in the loop, errors."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import plantsim


def test_every_world_format_loads(source, data):
    assert plantsim.load_world(source / "data/worlds/plants/substation_yard.json").obstacles.shape[1] == 4
    ros = plantsim.load_world(str(data / "ros_maps/depot.yaml"))
    assert ros.obstacles.shape[0] > 10
    grid = plantsim.load_world(str(data / "anyangle/arena.map"), scen=str(data / "anyangle/arena.scen"), query=3)
    assert grid.floor[2] == pytest.approx(49)


def test_plan_length_is_the_known_optimum(data):
    w = plantsim.load_world(str(data / "worlds/world_N10.json"))
    p = plantsim.plan(w, "vg", goal="docked")
    assert p.status == "ok"
    assert p.length == pytest.approx(94.490208432, abs=1e-6)  # ../shared/data/README.md
    assert p.path.shape[1] == 2 and np.allclose(p.path[0], w.start[:2])
    assert p.stats["vertices"] > 0
    assert "vg" in plantsim.planners()


def test_run_equals_the_command_line(source, binary, tmp_path):
    world = source / "data/worlds/examples/corridor_crossing.json"
    r = plantsim.run(str(world), seed=5, out=tmp_path / "py")
    subprocess.run([binary, "run", str(world), "--seed", "5", "--out", str(tmp_path / "cli")], check=True,
                   capture_output=True)
    cli = json.loads((tmp_path / "cli" / "summary.json").read_text())
    for key in ("status", "docked", "time_s", "position_error_m", "heading_error_deg", "collisions", "driven_length_m"):
        assert r.summary[key] == cli[key], key
    rows = np.loadtxt(tmp_path / "cli" / "trajectory.csv", delimiter=",", skiprows=1, usecols=(0, 1, 2, 3))
    assert np.allclose(r.trajectory[:, :4], rows, atol=1e-4)
    assert r.columns[:4] == ["t_s", "x_m", "y_m", "yaw_rad"]
    assert (tmp_path / "py" / "run.png").exists() and (tmp_path / "py" / "summary.json").exists()


def test_a_controller_that_returns_plantsims_command_changes_nothing(source):
    world = plantsim.load_world(source / "data/worlds/examples/corridor_crossing.json")
    alone = plantsim.run(world, seed=3)
    seen = []

    def echo(obs):
        seen.append(obs.phase)
        return obs.builtin

    steered = plantsim.run(world, seed=3, controller=echo)
    assert np.array_equal(alone.trajectory, steered.trajectory)  # bit for bit
    assert steered.summary["steered_by"] == "python:echo" and "steered_by" not in alone.summary
    assert set(seen) == {"travel"}  # docking stays plantsim's


def test_a_docking_callable_steers_the_docking_phases(source):
    world = plantsim.load_world(source / "data/worlds/examples/corridor_crossing.json")
    alone = plantsim.run(world, seed=4)
    phases = set()

    def dock(obs):
        phases.add(obs.phase)
        return obs.builtin

    steered = plantsim.run(world, seed=4, docking=dock, controller_name="dock-echo")
    assert np.array_equal(alone.trajectory, steered.trajectory)
    assert "approach" in phases and "travel" not in phases
    # A docking callable that never moves: plantsim, still the referee, ends it without a dock.
    stalled = plantsim.run(world, seed=4, docking=lambda o: (0.0, 0.0), config={"timeout_s": 120})
    assert not stalled.docked and stalled.summary["failure"] is not None


def test_the_observation_holds_perception_only(source):
    world = plantsim.load_world(source / "data/worlds/examples/corridor_crossing.json")
    got = {}

    def look(obs):
        if not got:
            got.update(pose=obs.pose, cov=obs.covariance, ranges=obs.scan_ranges, angles=obs.scan_angles,
                       plan=obs.plan, staging=obs.staging, obstacles=obs.obstacles, t=obs.time, v=obs.velocity,
                       health=obs.health)
            got["names"] = [n for n in dir(obs) if not n.startswith("_")]
        return None

    plantsim.run(world, seed=1, controller=look)
    assert got["pose"].shape == (3,) and got["cov"].shape == (3, 3)
    assert np.all(np.linalg.eigvalsh(got["cov"]) >= 0)
    assert got["ranges"].shape == got["angles"].shape and got["ranges"].size == 360
    assert got["plan"].shape[1] == 2 and got["obstacles"].shape[1] == 6 and got["health"] == "ok"
    assert not [n for n in got["names"] if "truth" in n or "true" in n]


def test_a_python_pursuit_docks_through_plantsims_docking(source):
    sys.path.insert(0, str(source / "examples/python"))
    from pursuit import make_pursuit
    r = plantsim.run(source / "data/worlds/examples/corridor_crossing.json", seed=2, controller=make_pursuit())
    assert r.docked, r.summary["failure"]
    assert r.summary["position_error_m"] < 0.02


def test_bad_input_is_an_input_error_with_the_command_lines_message(source, binary, tmp_path):
    with pytest.raises(plantsim.InputError, match="tracking"):
        plantsim.run(source / "data/worlds/examples/corridor_crossing.json", config={"tracking": {"no_such_key": 1}})
    bad = tmp_path / "bad.json"
    bad.write_text('{"floor": {"xmin": 0}}')
    with pytest.raises(plantsim.InputError) as e:
        plantsim.load_world(bad)
    cli = subprocess.run([binary, "plan", str(bad)], capture_output=True, text=True)
    assert cli.returncode == 2 and str(e.value) in cli.stderr
    with pytest.raises(plantsim.InputError, match="unknown planner"):
        plantsim.plan(source / "data/worlds/examples/corridor_crossing.json", "nope")
    with pytest.raises(plantsim.InputError, match="expected \\(v m/s, omega rad/s\\)"):
        plantsim.run(source / "data/worlds/examples/corridor_crossing.json", controller=lambda o: "fast")


def test_a_batch_from_a_dict_with_and_without_a_python_controller(source, tmp_path):
    scenario = {"name": "py", "worlds": [str(source / "data/worlds/examples/corridor_crossing.json")], "planners": ["vg"],
                "faults": {"none": {}}, "seeds": 3}
    builtin = plantsim.batch(scenario, tmp_path / "a", figures=False)
    assert builtin["episodes"] == 3 and builtin["rows"][0]["episodes"] == 3
    echo = plantsim.batch(scenario, tmp_path / "b", controller=lambda o: o.builtin, controller_name="echo",
                          figures=False)
    assert echo["succeeded"] == builtin["succeeded"]
    assert echo["fingerprint"] != builtin["fingerprint"]  # the controller's name is part of the ids
    lines = (tmp_path / "b" / "episodes.jsonl").read_text().splitlines()
    assert all('"steered_by":"echo"' in line and "+echo|" in line for line in lines)
    with pytest.raises(plantsim.InputError):
        plantsim.batch({"name": "bad", "worlds": ["missing.json"], "seeds": 1})


def test_help_tells_the_whole_call():
    doc = plantsim.run.__doc__
    for word in ("controller", "docking", "config", "seed", "planner", "out", "InputError"):
        assert word in doc


def test_shared_data_is_found_from_any_working_folder(source, tmp_path):
    # "$data/" resolves beside the checkout, as for the command line, not from the working folder.
    env = {k: v for k, v in os.environ.items() if k != "PLANTSIM_DATA"}
    env["PYTHONPATH"] = os.path.dirname(os.path.dirname(os.path.abspath(plantsim.__file__)))
    script = ("import plantsim; w = plantsim.load_world('$data/worlds/world_N10.json'); "
              "print(w.obstacles.shape[0])")
    out = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "10"
