"""rdmesh.Oracle subclasses: the optional intersect and the hint of locate."""

import math

import numpy as np
import pytest

import rdmesh
from mesh_checks import boundary_is_closed, euler_characteristic, volume_per_label


class BallWithoutIntersect(rdmesh.Oracle):
    """The ball |p - c| < r, without intersect: rdmesh bisects on locate."""

    def __init__(self, center, radius):
        super().__init__()
        self.c = np.asarray(center, dtype=float)
        self.r = float(radius)
        self.hints = []  # a sample of the hints given to locate

    def bounding_box(self):
        lo, hi = self.c - 1.2 * self.r, self.c + 1.2 * self.r
        return (*lo, *hi)

    def label(self, p):
        d = np.subtract(p, self.c)
        return 1 if d @ d < self.r * self.r else 0

    def locate(self, p, hint):
        if hint is not None and len(self.hints) < 1000:
            self.hints.append(hint)
        return self.label(p)

    def subdomains(self):
        return ["ball"]

    def patches(self):
        return [("sphere", 0, 1)]

    def initial_points(self, patch):
        n = 24  # a Fibonacci lattice on the sphere
        k = np.arange(n) + 0.5
        z = 1 - 2 * k / n
        phi = k * math.pi * (3 - math.sqrt(5))
        s = np.sqrt(1 - z * z)
        return self.c + self.r * np.stack([s * np.cos(phi), s * np.sin(phi), z], axis=1)

    def project(self, p, patch):
        d = np.subtract(p, self.c)
        n = math.sqrt(d @ d)
        return None if n == 0 else tuple(self.c + self.r * d / n)

    def tolerance(self):
        return 1e-10 * self.r


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
