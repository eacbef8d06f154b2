"""plantsim.load_plugin(): a plugin's components chosen by name from Python as from the command
line; a bad plugin raises InputError naming its file."""
import json
import pathlib

import pytest

import plantsim


def _test_plugin(binary, name):
    path = pathlib.Path(binary).parent / "tests" / "plugins" / f"libtest_plugin_{name}.so"
    if not path.exists():
        pytest.skip(f"{path} is not built")
    return str(path)


def test_a_plugin_controller_runs_from_python(source, binary, tmp_path):
    good = _test_plugin(binary, "good")
    loaded = plantsim.load_plugin(good)
    assert loaded["local_controllers"] == ["test-thrower", "test-map-refuser"]
    assert plantsim.load_plugin(good) == loaded  # loaded once
    names = [c["name"] for c in plantsim.components()["local_controllers"]]
    assert names[:3] == ["pure-pursuit", "mppi", "dwb"] and "test-thrower" in names
    thrower = next(c for c in plantsim.components()["local_controllers"] if c["name"] == "test-thrower")
    assert thrower["origin"] == good
    assert thrower["parameters"][0]["key"] == "test-thrower.throw_after_steps"
    config = tmp_path / "c.json"
    config.write_text(json.dumps({"local_controller": "test-thrower",
                                  "test-thrower": {"throw_after_steps": 20}}))
    r = plantsim.run(str(source / "data/worlds/examples/corridor_crossing.json"), config=str(config))
    assert not r.docked
    assert r.summary["failure"] == "plugin_error"


@pytest.mark.parametrize("name, says", [("wrong_abi", "ABI version"), ("clash", "clashes")])
def test_a_bad_plugin_raises_input_error_naming_its_file(binary, name, says):
    bad = _test_plugin(binary, name)
    with pytest.raises(plantsim.InputError) as e:
        plantsim.load_plugin(bad)
    assert bad in str(e.value) and says in str(e.value)
