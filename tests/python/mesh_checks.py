"""Properties every rdmesh volume mesh has, measured independently with numpy."""

import collections

import numpy as np


def signed_volumes(m):
    p = np.asarray(m.points)
    t = np.asarray(m.tets)
    a, b, c, d = (p[t[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


def volume_per_label(m):
    v = signed_volumes(m)
    return {int(label): float(v[m.tet_labels == label].sum()) for label in np.unique(m.tet_labels)}


def boundary_is_closed(m, patches=None):
    """Every edge of the chosen patches' triangles is shared by an even number of them."""
    tris = np.asarray(m.triangles)
    if patches is not None:
        tris = tris[np.isin(m.triangle_labels, patches)]
    count = collections.Counter()
    for a, b, c in tris:
        for e in ((a, b), (b, c), (c, a)):
            count[tuple(sorted(e))] += 1
    return all(n % 2 == 0 for n in count.values())


def euler_characteristic(m, patches):
    tris = np.asarray(m.triangles)[np.isin(m.triangle_labels, patches)]
    edges = {tuple(sorted(e)) for a, b, c in tris for e in ((a, b), (b, c), (c, a))}
    return len(np.unique(tris)) - len(edges) + len(tris)
