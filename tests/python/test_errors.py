"""Bad inputs and options raise the library's typed errors with the CLI's one-line
messages; Ctrl-C stops a run."""

import os
import pathlib
import signal
import threading

import pytest

import rdmesh

SAMPLES = pathlib.Path(__file__).resolve().parents[2] / "samples"
BOX = (-1.2, -1.2, -1.2, 1.2, 1.2, 1.2)


def test_hierarchy():
    for e in (rdmesh.InputError, rdmesh.OracleError, rdmesh.OutputError, rdmesh.InternalError,
              rdmesh.FidelityError):
        assert issubclass(e, rdmesh.Error) and issubclass(e, RuntimeError)


def test_missing_file(tmp_path):
    path = tmp_path / "nope.step"
    with pytest.raises(rdmesh.InputError, match=f"^{path}: no such file$"):
        rdmesh.mesh(path)


def test_unknown_extension(tmp_path):
    path = tmp_path / "a.xyz"
    path.write_text("1 2 3\n")
    with pytest.raises(rdmesh.InputError, match="unknown input extension '.xyz'"):
        rdmesh.mesh(path)


def test_bad_expression():
    with pytest.raises(rdmesh.InputError, match="^mesh_implicit: function 'domain': unknown variable 'w'"):
        rdmesh.mesh_implicit("x^2 + w", bbox=BOX)


def test_bad_options():
    with pytest.raises(TypeError, match="unknown option 'sise'"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, sise=0.1)
    with pytest.raises(TypeError):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, exude="no")
    with pytest.raises(rdmesh.InputError, match="radius"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, radius_edge=1.0)
    with pytest.raises(rdmesh.InputError, match="--features"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, features="sometimes")
    with pytest.raises(rdmesh.InputError, match="size"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=-1)


def test_domain_errors():
    with pytest.raises(rdmesh.InputError, match="^<domain>: missing 'bbox'"):
        rdmesh.mesh_domain({"functions": {"f": "x"}})
    with pytest.raises(rdmesh.InputError, match="matches no point"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 + 1", bbox=BOX)
    with pytest.raises(rdmesh.InputError, match="reach|box"):
        rdmesh.mesh_implicit(lambda x, y, z: x * 0 - 1, bbox=BOX)


def test_callable_errors_propagate():
    def f(x, y, z):
        raise ZeroDivisionError("from f")

    with pytest.raises(ZeroDivisionError, match="from f"):
        rdmesh.mesh_implicit(f, bbox=BOX)

    def wrong_shape(x, y, z):
        return x[:10] if hasattr(x, "shape") else x

    with pytest.raises(rdmesh.InputError, match="returned 10 values"):
        rdmesh.mesh_implicit(wrong_shape, bbox=BOX)


def test_time_limit_is_a_fidelity_error():
    with pytest.raises(rdmesh.FidelityError, match="time limit"):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.02, time_limit=1e-6)
    m = rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.02, time_limit=1e-6,
                             keep_bad_mesh=True)
    assert m.failed and m.report["refinement"]["time_limit_reached"]


def test_outputs(tmp_path):
    sample = SAMPLES / "sphere.json"
    m = rdmesh.mesh(sample, size=0.4)
    with pytest.raises(rdmesh.InputError, match="is the input file"):
        m.write(sample)
    with pytest.raises(rdmesh.InputError, match="unknown output extension '.xyz'"):
        m.write(tmp_path / "out.xyz")  # as the CLI: exit code 2
    with pytest.raises(rdmesh.OutputError, match="does not exist"):
        m.write(tmp_path / "missing" / "out.msh")
    with pytest.raises(rdmesh.OutputError, match="png"):
        m.picture(tmp_path / "out.jpg")
    with pytest.raises(rdmesh.InputError):
        m.picture(tmp_path / "out.png", view="sideways")
    assert list(tmp_path.iterdir()) == []


def test_progress_callback_and_interrupt():
    seen = []
    rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.1, progress=seen.append)
    assert seen and {"vertices", "cell_queue", "elapsed_seconds"} <= set(seen[-1])

    def stop(p):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.1, progress=stop)


def test_sigint_stops_a_run_without_python_code():
    """Ctrl-C during a run whose oracle is all C++ (the GIL is released)."""
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", bbox=BOX, size=0.015, exude=False)
    finally:
        timer.cancel()
