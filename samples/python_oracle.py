"""A domain written in Python: a ball as an rdmesh.Oracle subclass, meshed and checked.

The oracle answers the same queries as the C++ interface (oracles/include/rdmesh/oracle.h):
its bounding box, the label of a point, a crossing of a segment with the boundary,
the subdomains and patches, initial points on each patch, projections and the
accuracy of its points. Here the segment query solves the sphere's quadratic exactly.

Every query is a call into Python made by the refiner, several hundred thousand per
mesh: a Python oracle is one to two orders of magnitude slower than the same domain
given as an expression (rdmesh.mesh_implicit("x^2 + y^2 + z^2 - 1", ...)), which is
compiled to bytecode and evaluated in C++ without the interpreter. Use it for
geometry that has no expression: a lookup in your own data structure, a CAD kernel
with Python bindings.

Run: PYTHONPATH=build/python python3 samples/python_oracle.py [OUT.msh]
"""

import math
import sys

import numpy as np

import rdmesh


class Ball(rdmesh.Oracle):
    """Subdomain 1 = the ball |p - center| < radius; one patch, its sphere."""

    def __init__(self, center, radius):
        super().__init__()
        self.c = np.asarray(center, dtype=float)
        self.r = float(radius)

    def bounding_box(self):
        lo, hi = self.c - 1.2 * self.r, self.c + 1.2 * self.r
        return (*lo, *hi)

    def locate(self, p):
        d = np.subtract(p, self.c)
        return 1 if d @ d < self.r * self.r else 0

    def intersect(self, a, b):
        """The crossing of [a, b] with the sphere nearest to a, when the labels differ."""
        a, b = np.asarray(a), np.asarray(b)
        if self.locate(a) == self.locate(b):
            return None
        d, m = b - a, a - self.c
        qa, qb, qc = d @ d, 2 * (d @ m), m @ m - self.r * self.r
        root = math.sqrt(max(qb * qb - 4 * qa * qc, 0.0))
        for t in sorted(((-qb - root) / (2 * qa), (-qb + root) / (2 * qa))):
            if 0.0 <= t <= 1.0:
                return tuple(a + t * d), 1
        return tuple(a + min(max(-qb / (2 * qa), 0.0), 1.0) * d), 1

    def subdomains(self):
        return ["ball"]

    def patches(self):
        return [("sphere", 0, 1)]  # (name, label on one side, label on the other)

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
        return 1e-12 * self.r


def main():
    ball = Ball(center=(0.5, 0.0, -0.25), radius=1.0)
    m = rdmesh.mesh_oracle(ball, size=0.25)
    p, t = m.points, m.tets
    a, b, c, d = (p[t[:, i]] for i in range(4))
    volumes = np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6
    volume = volumes.sum()
    exact = 4 / 3 * math.pi
    allowed = m.report["criteria"]["facet_distance"] * 4 * math.pi
    edges = {tuple(sorted(e)) for tri in m.triangles for e in ((tri[0], tri[1]), (tri[1], tri[2]),
                                                               (tri[2], tri[0]))}
    euler = len(np.unique(m.triangles)) - len(edges) + len(m.triangles)
    print(f"{len(p)} vertices, {len(t)} tetrahedra, {len(m.triangles)} triangles; "
          f"volume {volume:.4f} (exact {exact:.4f}, allowed +-{allowed:.4f}); Euler {euler}")
    if len(sys.argv) > 1:
        m.write(sys.argv[1])
    ok = (volumes > 0).all() and abs(volume - exact) <= allowed and euler == 2
    ok = ok and m.subdomain_names == ["ball"] and m.patch_names == ["sphere"]
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
