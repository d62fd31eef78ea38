"""rdmesh.Oracle subclasses: the optional intersect and the hint of locate."""

import math
import pathlib
import sys

import numpy as np
import pytest

import rdmesh
from mesh_checks import boundary_is_closed, euler_characteristic, volume_per_label

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "samples"))
from python_oracle import Ball  # noqa: E402  (the sample's ball, which defines intersect)


class BallWithoutIntersect(rdmesh.Oracle):
    """The sample's ball without intersect (rdmesh then bisects on locate), whose
    locate takes the hint."""

    def __init__(self, center, radius):
        super().__init__()
        self.c = np.asarray(center, dtype=float)
        self.r = float(radius)
        self.hints = []  # a sample of the hints given to locate

    bounding_box = Ball.bounding_box
    label = Ball.locate
    subdomains = Ball.subdomains
    patches = Ball.patches
    initial_points = Ball.initial_points
    project = Ball.project
    tolerance = Ball.tolerance

    def locate(self, p, hint):
        if hint is not None and len(self.hints) < 1000:
            self.hints.append(hint)
        return self.label(p)


def test_oracle_without_intersect_meshes_a_ball():
    ball = BallWithoutIntersect(center=(0.5, 0.0, -0.25), radius=1.0)
    m = rdmesh.mesh_oracle(ball, size=0.3)
    assert len(m.tets) > 100
    assert boundary_is_closed(m)
    assert euler_characteristic(m, [1]) == 2
    # The fidelity check's bound: the facet distance times the sphere's area.
    allowed = m.report["criteria"]["facet_distance"] * 4 * math.pi
    assert volume_per_label(m)[1] == pytest.approx(4 / 3 * math.pi, abs=allowed)
    # Every boundary vertex lies on the sphere within the bisection's accuracy.
    on_surface = np.unique(m.triangles)
    radii = np.linalg.norm(m.points[on_surface] - ball.c, axis=1)
    assert np.abs(radii - 1.0).max() < 1e-6
    # locate(p, hint) was given hints: points with their true labels.
    assert ball.hints
    for point, label in ball.hints:
        assert ball.label(point) == label


class LabelAndCrossing(BallWithoutIntersect):
    """locate returns (label, None): the tuple form is accepted."""

    def locate(self, p, hint):
        return self.label(p), None


def test_locate_may_return_label_and_crossing():
    m = rdmesh.mesh_oracle(LabelAndCrossing(center=(0, 0, 0), radius=1.0), size=0.4)
    assert euler_characteristic(m, [1]) == 2


class BadLocate(BallWithoutIntersect):
    def locate(self, p):
        return (1, 2, 3)


def test_locate_returning_garbage_is_an_oracle_error():
    with pytest.raises(rdmesh.OracleError, match="locate must return a label or"):
        rdmesh.mesh_oracle(BadLocate(center=(0, 0, 0), radius=1.0), size=0.4)
