# Copyright (c) 2026 The CGAL BODT_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""B-ODT tetrahedral mesh smoothing, flips and vertex insertion, from Python.

    import bodt, meshio
    mesh, report = bodt.smooth(meshio.read("in.mesh"))
    mesh.write("out.vtu")

The work is done by the same C++ code as the command-line tool `bodt smooth`.
"""

import json
import warnings
from collections import namedtuple

import numpy as np

from . import _bodt

__version__ = _bodt.__version__

#: The mesh as arrays, as `smooth` takes and returns it: `points` (n, 3) floats,
#: `tets` (m, 4) vertex indices from 0, `labels` (m,) subdomain of each
#: tetrahedron, `triangles` (k, 3) boundary and interface triangles and
#: `triangle_labels` (k,) their surface patches.
Mesh = namedtuple("Mesh", ["points", "tets", "labels", "triangles", "triangle_labels"])

# Where meshio keeps the labels, by reader: Medit, Gmsh, then generic names.
_LABEL_KEYS = ("medit:ref", "gmsh:physical", "cell_tags", "CellEntityIds")


def smooth(points, tets=None, labels=None, triangles=None, triangle_labels=None, **options):
    """Improves the dihedral angles of a tetrahedral mesh; returns (mesh, report).

    Called with NumPy arrays (`smooth(points, tets, labels=None, triangles=None,
    triangle_labels=None, **options)`), it returns a `bodt.Mesh` of arrays; called
    with a `meshio.Mesh` (`smooth(mesh, **options)`), it returns a new
    `meshio.Mesh` with the tetrahedra, triangles and line cells (feature edges)
    and their labels. Tetrahedra labelled 0 are outside the mesh unless all are.
    The report is a dict: the options, the result and its totals, every sweep,
    and the quality before and after (the JSON report of `bodt smooth`).

    Options, with the defaults of `bodt smooth`: max_iteration_number (20; 0: until
    a sweep changes nothing, at most 1000), time_limit (seconds, 0: none),
    convergence (0: off), method ('bodt', 'odt' or 'flips'), preserve_features,
    quality_guard, topology_optimization, vertex_insertion (all True),
    max_vertex_insertions (-1: 5% of the vertices), feature_edge_ratio and
    feature_corner_ratio (0.05). An invalid mesh raises ValueError naming what is
    wrong; an unknown option raises TypeError.
    """
    if tets is None and hasattr(points, "cells") and hasattr(points, "points"):
        return _smooth_meshio(points, options)
    if tets is None:
        raise TypeError("smooth() needs the tetrahedra: smooth(points, tets, ...) or smooth(meshio_mesh)")
    result, report = _smooth(points, tets, labels, triangles, triangle_labels, None, options)
    return Mesh(*result[:5]), report


def _smooth(points, tets, labels, triangles, triangle_labels, edges, options):
    out = _bodt.smooth_arrays(np.asarray(points, dtype=float), np.asarray(tets), labels,
                              None if triangles is None else np.asarray(triangles), triangle_labels,
                              None if edges is None else np.asarray(edges), options)
    if out[7]:
        for line in out[7].splitlines():
            warnings.warn(line, stacklevel=3)
    return out[:6], json.loads(out[6])


def _smooth_meshio(mesh, options):
    import meshio

    key = next((k for k in _LABEL_KEYS if k in mesh.cell_data), None)
    blocks = {"tetra": [], "triangle": [], "line": []}
    block_labels = {"tetra": [], "triangle": [], "line": []}
    for i, block in enumerate(mesh.cells):
        if block.type not in blocks:
            raise ValueError("meshio mesh: cells of type '%s' are not supported (tetra, triangle, line are)"
                             % block.type)
        blocks[block.type].append(np.asarray(block.data))
        if key is not None:
            block_labels[block.type].append(np.asarray(mesh.cell_data[key][i]).reshape(-1))

    def joined(kind, columns):
        if not blocks[kind]:
            return None, None
        data = np.concatenate(blocks[kind]).reshape(-1, columns)
        labels = np.concatenate(block_labels[kind]) if key is not None else None
        return data, labels

    tets, labels = joined("tetra", 4)
    if tets is None:
        raise ValueError("meshio mesh: no tetrahedra")
    triangles, triangle_labels = joined("triangle", 3)
    edges, edge_labels = joined("line", 2)
    result, report = _smooth(mesh.points, tets, labels, triangles, triangle_labels, edges, options)
    points, tets, labels, triangles, triangle_labels, edges = result

    cells = [("tetra", tets)]
    cell_labels = [labels]
    if triangles.shape[0] > 0:
        cells.append(("triangle", triangles))
        cell_labels.append(triangle_labels)
    if edges.shape[0] > 0:
        cells.append(("line", edges))
        cell_labels.append(edge_labels if edge_labels is not None and len(edge_labels) == len(edges)
                           else np.ones(len(edges), dtype=np.int64))
    cell_data = {key: cell_labels} if key is not None else {}
    # Data attached to the vertices still fits when no vertex was added.
    point_data = dict(mesh.point_data) if len(points) == len(mesh.points) else {}
    return meshio.Mesh(points, cells, point_data=point_data, cell_data=cell_data,
                       field_data=dict(mesh.field_data)), report
