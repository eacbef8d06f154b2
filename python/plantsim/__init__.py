"""plantsim from Python: load worlds, plan, run episodes (with your own controller in the
loop) and batches, and import Nav2 parameters. Built into build/python by the README's set-up;

    PYTHONPATH=build/python /usr/bin/python3 -c "import plantsim"

Everything here runs the same C++ as the command line: the same loaders (and error messages,
raised as plantsim.InputError, a ValueError), the same episode, the same batch records.
A controller you pass to run() or batch() sees only the robot's perception (plantsim.Observation),
never the simulator's truth. docs/python.md has the whole guide.
"""
import csv
import io
import json
import os
import pathlib
import tempfile


def _find_shared_data():
    """The shared data folder ("$data/" in scenarios and world paths) beside the checkout this
    module was built in, as the command line finds it beside its binary: the C++ side looks beside
    the running executable, which here is the Python interpreter, and fell back to a folder
    relative to the working folder (a shipped scenario then failed from anywhere else)."""
    for folder in pathlib.Path(__file__).resolve().parents:
        if (folder / "shared" / "data").is_dir():
            return str(folder / "shared" / "data")
    return None


if not os.environ.get("PLANTSIM_DATA") and _find_shared_data():
    os.environ["PLANTSIM_DATA"] = _find_shared_data()  # read by the C++ loaders; yours wins

from ._plantsim import (PHASES, InputError, Observation, Plan, Run, World, components, load_plugin, load_world,
                        nav2_import, plan, planners, run)
from ._plantsim import _batch, _tune
from .env import Env, VectorEnv, _absolute_worlds
from .registry import make, make_vec, register
from .async_env import AsyncVectorEnv

__all__ = ["PHASES", "AsyncVectorEnv", "Env", "InputError", "Observation", "Plan", "Run", "VectorEnv", "World", "batch", "components",
           "load_plugin", "load_world", "make", "make_vec", "nav2_import", "plan", "planners", "register", "run",
           "tune"]


def _number(text):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def batch(scenario, out=None, *, controller=None, docking=None, controller_name="", threads=0, figures=True,
          fresh=False, progress=False, records=True):
    """Runs a scenario as `plantsim batch SCENARIO --out OUT` does; returns its summary.

    scenario: a scenario file's path, or a dict with the same keys (docs/batch.md); a dict's
    relative world paths are taken from the working folder.
    out: the output folder (episodes.jsonl, summary.csv, report.html); None: a temporary folder,
    removed afterwards. An existing folder of the same scenario is resumed unless fresh=True.
    controller, docking, controller_name: as for run(); with a controller every episode is steered
    by it, on one thread, and its name joins each controller's name in the episode ids.
    threads: 0 for one per core. figures: draw the report's charts.
    Returns a dict: "rows" (one dict per configuration, the columns of summary.csv), "episodes",
    "ran", "skipped", "succeeded" (over every episode in the folder, as the rows count),
    "succeeded_now" (of those this call ran), "collisions" (this call's), "fingerprint", "out".
    "records": every episode's record in the folder, a dict each (the lines of OUT/episodes.jsonl,
    docs/batch.md); records=False leaves them out (a million episodes take about a GB as dicts).
    The batch runs with the GIL released; Ctrl-C raises KeyboardInterrupt within a fraction of a
    second, the finished episodes kept in episodes.jsonl (the same call again resumes them).
    """
    with tempfile.TemporaryDirectory(prefix="plantsim_batch_") as scratch:
        if isinstance(scenario, dict):
            path = os.path.join(scratch, "scenario.yaml")
            with open(path, "w", encoding="utf-8") as f:
                json.dump(_absolute_worlds(scenario), f)  # JSON is YAML
        else:
            path = os.fspath(scenario)
        folder = os.fspath(out) if out is not None else os.path.join(scratch, "out")
        result = _batch(path, folder, controller, docking, controller_name, threads, figures, fresh, progress)
        rows = [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(io.StringIO(result.pop("summary_csv")))]
        result["rows"] = rows
        result["out"] = folder if out is not None else None
        if records:
            with open(os.path.join(folder, "episodes.jsonl"), encoding="utf-8") as f:
                result["records"] = [json.loads(line) for line in f if line.strip()]
        return result


def tune(scenario, out, *, params=(), budget=None, objective=None, method=None, min_wilson=None, seed=1,
         threads=0, figures=True, fresh=False, progress=False):
    """Tunes episode parameters as `plantsim tune SCENARIO --out OUT` does; returns its summary.

    scenario: a scenario file with a `tune:` section naming its held-out validation worlds or seeds
    (docs/tune.md). out: the output folder (evaluations.jsonl, best.json, report.html); an earlier
    tuning of the same settings there is resumed unless fresh=True.
    params: "KEY=LOW:HIGH" strings (docs/config.md's keys); empty: the scenario's tune.parameters,
    else pure pursuit's and the docking approach's. budget: evaluations for NLopt and as many for
    random search (default 60). objective: "success_then_time" (default), "time", "docking_error",
    "contacts" or "success". method: NLopt's "sbplx" (default), "sbplx-starts", "bobyqa",
    "neldermead", "crs2" or "isres". min_wilson: the constrained objectives' success floor (default: the defaults' own).
    Returns OUT/summary.json as a dict: "settings" (default, nlopt, random: values, tuning score,
    tuning and validation statistics), "best", "tuned_against_default_on_validation" (paired tests),
    "verdict". Runs with the GIL released; Ctrl-C raises KeyboardInterrupt between episodes, the
    finished evaluations kept for the next call.
    """
    return _tune(os.fspath(scenario), os.fspath(out), list(params), budget, objective, method, min_wilson, seed,
                 threads, figures, fresh, progress)
