"""Where the Python tests find the project, the shared data and the command-line binary
(set by ctest: tests/CMakeLists.txt)."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("PLANTSIM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATA = pathlib.Path(os.environ.get("PLANTSIM_SHARED_DATA", SOURCE.parent / "shared" / "data"))
BINARY = os.environ.get("PLANTSIM_BINARY", str(SOURCE / "build" / "plantsim"))


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def data():
    return DATA


@pytest.fixture
def binary():
    return BINARY
