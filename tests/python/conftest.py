"""Shared fixtures of the Python suite: where the data and the antslam program are (CTest
passes them in the environment, tests/python/CMakeLists.txt), and running the program."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("ANTSLAM_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
DATA = SOURCE / "data"
GRAPHS = SOURCE / "tests" / "slamgraph" / "graphs"


@pytest.fixture
def program():
    """Runs the antslam program with the given arguments; returns its stdout."""
    path = os.environ.get("ANTSLAM_PROGRAM")
    if not path:
        pytest.skip("the antslam program is not built (ANTSLAM_PROGRAM unset)")

    def run(*args):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout
    return run
