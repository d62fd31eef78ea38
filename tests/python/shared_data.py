"""The Python side of tests/shared_data.h: the real inputs the tests mesh.

The folder is $RDMESH_DATA_DIR, else ../shared/data beside the checkout. When it
(or a file in it) is missing, a test that needs it is skipped on a developer's
machine and FAILS when the environment variable CI is set (to anything but ""
or "0")."""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]


def shared_data_dir():
    env = os.environ.get("RDMESH_DATA_DIR")
    if env and os.path.isdir(env):
        return pathlib.Path(env)
    beside = SOURCE_DIR.parent / "shared" / "data"
    return beside if beside.is_dir() else None


def in_ci():
    return os.environ.get("CI", "") not in ("", "0")


def needed(what):
    """Skips the test for lack of `what`, or fails it when CI is set."""
    if in_ci():
        pytest.fail(f"{what} is absent; CI is set, so this is a failure, not a skip")
    pytest.skip(f"{what} is absent")


def needed_module(name):
    """The module `name` (meshio...), imported; skips (fails under CI) when absent."""
    try:
        return __import__(name)
    except ImportError:
        needed(f"the Python module {name}")


def shared_data(relative):
    """The path of `relative` in the data folder; skips (fails under CI) when absent."""
    folder = shared_data_dir()
    path = folder / relative if folder else None
    if path is None or not path.exists():
        needed(f"shared data file {relative}")
    return path
