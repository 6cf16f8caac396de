# Copyright (c) 2026 The CGAL BODT_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""B-ODT tetrahedral mesh smoothing, flips and vertex insertion, from Python.

    import bodt, meshio
    mesh, report = bodt.smooth(meshio.read("in.msh"))
    mesh.write("out.vtu")

`smooth` improves the dihedral angles of a mesh and `quality` measures them;
both take a `meshio.Mesh` or NumPy arrays (see `Mesh`). The work is done by the
same C++ code as the command-line tool (`bodt smooth`, `bodt quality`).
"""

import importlib.util
import json
import warnings
from collections import namedtuple

import numpy as np

try:
    from . import _bodt
except ImportError:
    # Without the compiled part Python would only say that the name cannot be
    # imported "from partially initialized module 'bodt'"; say what to build.
    if importlib.util.find_spec(__name__ + "._bodt") is not None:
        raise   # it is there but does not load: Python's message says why
    raise ImportError(
        "bodt: the compiled part of the module, bodt._bodt, is missing next to %s. Install the package with "
        "`python3 -m pip install --no-build-isolation .` from the repository's root (README.md, 'Use it from "
        "Python'), or build it in the build tree with `cmake --build build --target _bodt` and set "
        "PYTHONPATH=build/python." % __file__) from None

__version__ = _bodt.__version__
__all__ = ["Mesh", "smooth", "quality", "__version__"]

Mesh = namedtuple("Mesh", ["points", "tets", "labels", "triangles", "triangle_labels"])
Mesh.__doc__ = """A mesh as arrays, as `smooth` takes and returns it without meshio.

points: (n, 3) floats; tets: (m, 4) vertex indices from 0; labels: (m,) the
subdomain of each tetrahedron; triangles: (k, 3) boundary and interface triangles;
triangle_labels: (k,) their surface patches."""
Mesh.points.__doc__ = "(n, 3) float array: the vertices"
Mesh.tets.__doc__ = "(m, 4) integer array: the tetrahedra, as vertex indices from 0"
Mesh.labels.__doc__ = "(m,) integer array: the subdomain of each tetrahedron (0: outside, unless all are 0)"
Mesh.triangles.__doc__ = "(k, 3) integer array: boundary and interface triangles"
Mesh.triangle_labels.__doc__ = "(k,) integer array: the surface patch of each triangle"

# Where meshio keeps the labels, by reader: Medit, Gmsh, then generic names.
_LABEL_KEYS = ("medit:ref", "gmsh:physical", "cell_tags", "CellEntityIds")


def smooth(points, tets=None, labels=None, triangles=None, triangle_labels=None, progress=None, **options):
    """Improves the dihedral angles of a tetrahedral mesh; returns (mesh, report).

    Called with NumPy arrays, smooth(points, tets, labels=None, triangles=None,
    triangle_labels=None, **options), it returns a `bodt.Mesh` of arrays; called with
    a `meshio.Mesh`, smooth(mesh, **options), it returns a new `meshio.Mesh` with the
    tetrahedra, triangles and line cells (feature edges) and their labels. Labels
    default to 1; tetrahedra labelled 0 are outside the mesh unless all are. The
    report is a dict: the options, the result and its totals, every sweep, and the
    quality before and after (the JSON report of `bodt smooth`).

    progress: None, or a function called after every sweep with that sweep's
        statistics as a dict (the report's "per_iteration" entries: iteration, phase,
        moved, refused, max_relative_move, topology, insertion, seconds, ...). An
        exception it raises (or Ctrl-C) stops the run and propagates; the input is
        left as it was.

    Options, with the defaults of `bodt smooth`:

    max_iteration_number (20; also spelt iterations): sweeps of the main phase, and
        the most each largest-angle phase runs; 0: until a sweep changes nothing or
        `convergence` is reached, at most 1000.
    time_limit (0: none): seconds; the run stops after the sweep that passes it.
    convergence (0: off): stop when no vertex moved by more than this fraction of
        its local size.
    freeze_bound (0.0003): a vertex whose move is shorter than this fraction of its
        local size stays put until a neighbour moves; 0: every vertex moves every time.
    max_boundary_distance (0: no bound): a step that takes the boundary or an interface
        farther than this from the input's, or the input's farther from them
        (relative to the largest side of its bounding box), is refused; 0: no bound.
    method ('bodt'): 'bodt', every vertex moves; 'odt', interior vertices only;
        'flips', no vertex moves (flips and insertion alone); 'nodt', boundary
        vertices by Natural ODT, projected back onto the input's boundary (the
        volume is not kept).
    preserve_features (True): False lets every boundary vertex slide on its tangent
        plane, feature curves and corners included.
    quality_guard (True): refuse a move that makes the worst cells around the
        vertex worse or takes an angle outside the input's extremes.
    topology_optimization (True): flips after each sweep.
    vertex_insertion (True): vertices inserted at spades, caps, slivers and wedges.
    max_vertex_insertions (-1: 5% of the input's vertices): at most this many.
    worst_cell_phase (True): after the last phase, max-min steps and flips at the
        cells within 2 degrees of the worst, until the extreme angles stop improving.
    ear_splits (False): boundary ears (two boundary faces meeting above the
        largest-angle threshold) split at their inner edge, in the main and the
        largest-angle phases: a lower largest angle on curved Mesh_3 outputs, at
        some cost in the smallest on some meshes.
    cavity_insertion (True): in the worst-cell phase (which then always runs),
        interior vertices at the worst cells, each with its cavity and place chosen
        together: higher smallest angles on curved Mesh_3 outputs, more time.
    edge_contraction (False): in the last phase, vertices inside a subdomain or on
        a flat part of the surface removed where that raises the worst cell.
    max_vertex_removals (-1: 5% of the input's vertices): at most this many.
    max_min_threshold (0.34): max-min steps at the vertices of cells whose smallest
        dihedral sine is below this (about 20 degrees); 0: none.
    largest_angle_phase (True): after the main phase, one decided by the largest
        dihedral angle, then one by the smallest again.
    largest_angle_threshold (120): degrees; in that phase, cells with a larger
        angle get max-min steps.
    threads (0: every core): threads of the sweeps; the result does not depend on it.
    feature_angle (25.21): degrees in (0, 90]. In a mesh with no feature
        information (edges, corners, two or more surface patches), tensor voting
        takes as features the edges where the surface turns by more than this;
        larger: fewer features, more vertices free to move.
    corner_angle (30.27): degrees in (0, 90]; ... and as corners (which do not move)
        the vertices where three sides meet with normals more than this apart.
    feature_edge_ratio, feature_corner_ratio (0.05, 0.05): the same two thresholds
        as the library's eigenvalue ratios (feature_angle A is the ratio
        tan^2(A / 2)). Give angles or ratios, not both.

    An invalid mesh raises ValueError naming what is wrong (an index out of range, a
    repeated or flat tetrahedron, a face of three tetrahedra); an unknown option
    raises TypeError. The smoothing runs without the GIL.
    """
    if progress is not None and not callable(progress):
        raise TypeError("progress must be a function of one argument, or None")
    if tets is None and hasattr(points, "cells") and hasattr(points, "points"):
        return _smooth_meshio(points, progress, options)
    if tets is None:
        raise TypeError("smooth() needs the tetrahedra: smooth(points, tets, ...) or smooth(meshio_mesh)")
    result, report = _smooth(points, tets, labels, triangles, triangle_labels, None, progress, options)
    return Mesh(*result[:5]), report


def quality(points, tets=None, labels=None, **options):
    """Measures the dihedral angles of a tetrahedral mesh; returns a dict.

    Takes a `meshio.Mesh`, quality(mesh, **options), or arrays, quality(points, tets,
    labels=None, **options), and checks them as `smooth` does. The dict is the
    output of `bodt quality --json`: num_vertices, num_tets, min_dihedral_deg,
    max_dihedral_deg, the tetrahedra with an angle below small_angle and above
    large_angle (tets_below_10deg, tets_above_170deg by default), bad_tets by where
    they are, min_boundary_triangle_angle_deg (the smallest angle of a boundary or
    interface triangle; None without one), min_radius_ratio, mean_radius_ratio,
    volume, volume_per_subdomain,
    inverted_tets and the histogram of all six angles of every tetrahedron.

    Options: bins (36): histogram bins over [0, 180] degrees; small_angle (10) and
    large_angle (170): degrees, the bounds of a bad tetrahedron; threads (0: every
    core): the result does not depend on it.
    """
    if tets is None and hasattr(points, "cells") and hasattr(points, "points"):
        arrays = _meshio_arrays(points)
        points, tets, labels = points.points, arrays["tetra"][0], arrays["tetra"][1]
    elif tets is None:
        raise TypeError("quality() needs the tetrahedra: quality(points, tets, ...) or quality(meshio_mesh)")
    text, notes = _bodt.quality_arrays(np.asarray(points, dtype=float), np.asarray(tets), labels, options)
    _warn(notes)
    return json.loads(text)


def _warn(notes):
    for line in notes.splitlines():
        warnings.warn(line, stacklevel=3)


def _smooth(points, tets, labels, triangles, triangle_labels, edges, progress, options):
    each_sweep = None if progress is None else (lambda text: progress(json.loads(text)))
    out = _bodt.smooth_arrays(np.asarray(points, dtype=float), np.asarray(tets), labels,
                              None if triangles is None else np.asarray(triangles), triangle_labels,
                              None if edges is None else np.asarray(edges), options, each_sweep)
    _warn(out[7])
    return out[:6], json.loads(out[6])


def _meshio_arrays(mesh):
    """The tetra, triangle and line cells of a meshio mesh, each as (cells, labels) or (None, None)."""
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

    arrays = {kind: joined(kind, columns) for kind, columns in (("tetra", 4), ("triangle", 3), ("line", 2))}
    if arrays["tetra"][0] is None:
        raise ValueError("meshio mesh: no tetrahedra")
    arrays["key"] = key
    return arrays


def _smooth_meshio(mesh, progress, options):
    import meshio

    arrays = _meshio_arrays(mesh)
    key = arrays["key"]
    tets, labels = arrays["tetra"]
    triangles, triangle_labels = arrays["triangle"]
    edges, edge_labels = arrays["line"]
    result, report = _smooth(mesh.points, tets, labels, triangles, triangle_labels, edges, progress, options)
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
