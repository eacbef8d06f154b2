"""plantsim.tune (issue 55): the same tuning as `plantsim tune`, its summary as a dict, bad input
as InputError before any episode, and Ctrl-C stopping it between episodes with its finished
evaluations kept for the next call."""
import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

import plantsim
from test_threads_and_signals import MODULE_PATH


def scenario(tmp_path, source, seeds=2):
    worlds = [str(source / "data/worlds/examples/small_plant.json"), str(source / "data/worlds/examples/corridor_crossing.json")]
    path = tmp_path / "t.yaml"
    path.write_text(json.dumps({"name": "tiny", "worlds": worlds, "seeds": seeds,
                                "tune": {"validation_seeds": [101, 102]}}))  # JSON is YAML
    return path


def test_tune_matches_the_command_and_returns_its_summary(source, binary, tmp_path):
    path = scenario(tmp_path, source)
    params = ["tracking.max_linear_speed_mps=0.3:0.8"]
    summary = plantsim.tune(path, tmp_path / "py", params=params, budget=2, figures=False)
    assert summary["kind"] == "tune"
    assert [s["setting"] for s in summary["settings"]] == ["default", "nlopt", "random"]
    assert summary["validation_episodes"] == 4
    subprocess.run([binary, "tune", str(path), "--param", params[0], "--budget", "2", "--out",
                    str(tmp_path / "cli"), "--quiet", "--no-figures"], check=True, capture_output=True)
    assert (tmp_path / "py/best.json").read_text() == (tmp_path / "cli/best.json").read_text()


def test_bad_input_is_an_input_error_before_any_episode(source, tmp_path):
    path = scenario(tmp_path, source)
    with pytest.raises(plantsim.InputError, match="documented range"):
        plantsim.tune(path, tmp_path / "o", params=["lidar.dropout_probability=0:2"])
    with pytest.raises(plantsim.InputError, match="--budget"):
        plantsim.tune(path, tmp_path / "o", budget=0)
    assert not (tmp_path / "o").exists()


def test_ctrl_c_stops_a_tuning_keeping_its_finished_evaluations(source, tmp_path):
    path = scenario(tmp_path, source, seeds=30)
    folder = tmp_path / "t"
    script = f"""
        import os, signal, threading, time, plantsim
        threading.Timer(4.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        started = time.monotonic()
        try:
            plantsim.tune({str(path)!r}, {str(folder)!r}, budget=50, figures=False)
            print("finished")
        except KeyboardInterrupt:
            print("interrupted", round(time.monotonic() - started - 4.0, 3))
    """
    out = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], env=dict(os.environ, PYTHONPATH=MODULE_PATH),
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    words = out.stdout.split()
    assert words[0] == "interrupted", out.stdout
    assert float(words[1]) < 2.0, out.stdout  # between episodes: well under an episode
    lines = (folder / "evaluations.jsonl").read_text().splitlines()
    assert 0 < len(lines) < 101
    assert all(line.endswith("}") for line in lines)
    assert not (folder / "best.json").exists()
