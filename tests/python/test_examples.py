"""The examples under examples/python run and say what they measured (small sizes here)."""
import os
import subprocess
import sys

import pytest


def run_example(source, name, *args):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([env.get("PYTHONPATH", ""), str(source / "examples/python")])
    out = subprocess.run([sys.executable, str(source / "examples/python" / name), *args], cwd=source, env=env,
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_race(source):
    out = run_example(source, "race.py", "--seeds", "2")
    assert "plantsim  docked 2/2" in out and "echo      docked 2/2" in out
    assert "a Python controller in the loop costs" in out


def test_sweep_plots(source, tmp_path):
    png = tmp_path / "sweep.png"
    out = run_example(source, "sweep.py", "--seeds", "1", "--speeds", "0.4,0.6", "--out", str(png))
    assert "max_linear_speed_mps 0.40: docked" in out
    pytest.importorskip("matplotlib")
    import matplotlib.image as mpimg
    pixels = mpimg.imread(png)
    assert pixels.shape[0] > 300 and pixels.shape[1] > 800
    assert (pixels[..., :3].std(axis=2) > 0.1).any()  # something coloured was drawn (the green line)


def test_inspect(source):
    out = run_example(source, "inspect_episode.py", "--seed", "2")
    assert "observations from t = 1.00 s" in out and "steered_by recorder" in out


def test_learn_to_dock_plots(source, tmp_path):
    png = tmp_path / "learn.png"
    out = run_example(source, "learn_to_dock.py", "--iterations", "2", "--envs", "2", "--max-steps", "300",
                      "--held-out-starts", "1", "--held-out-max-steps", "200", "--out", str(png))
    assert "iteration  2: tuning docked" in out and "held-out seeds: docked" in out
    assert "held-out generated plants (six styles, 6 starts): docked" in out
    pytest.importorskip("matplotlib")
    import matplotlib.image as mpimg
    assert mpimg.imread(png).shape[1] > 800
