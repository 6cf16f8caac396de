# Copyright (c) 2026 The CGAL BODT_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the Python module bodt, run by ctest (python3 -m unittest).

The environment gives BODT_BINARY (the command-line tool, to check that both run
the same C++ code) and BODT_TEST_TMP (a scratch folder).
"""

import itertools
import json
import math
import os
import re
import shutil
import subprocess
import sys
import unittest

import meshio
import numpy as np

import bodt

TMP = os.environ.get("BODT_TEST_TMP", "/tmp/bodt_python_test")
BODT_BINARY = os.environ.get("BODT_BINARY", "bodt")


def jittered_grid(n=4, two_labels=False):
    """The box [0, n]^3 of unit cubes, six tetrahedra each, interior points moved."""
    rng = np.random.default_rng(7)
    index = lambda i, j, k: (k * (n + 1) + j) * (n + 1) + i
    points = np.array([(i, j, k) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)], dtype=float)
    for k, j, i in itertools.product(range(1, n), repeat=3):
        points[index(i, j, k)] += rng.uniform(-0.15, 0.15, 3)
    tets, labels = [], []
    for k, j, i in itertools.product(range(n), repeat=3):
        for axes in itertools.permutations(range(3)):
            c = [i, j, k]
            t = [index(*c)]
            for a in axes:
                c[a] += 1
                t.append(index(*c))
            p = points[t]
            if np.linalg.det(np.array([p[1] - p[0], p[2] - p[0], p[3] - p[0]])) < 0:
                t[2], t[3] = t[3], t[2]
            tets.append(t)
            labels.append(2 if two_labels and i < n // 2 else 1)
    return points, np.array(tets), np.array(labels)


def min_dihedral_deg(points, tets):
    worst = 180.0
    for t in tets:
        p = points[t]
        for a, b in itertools.combinations(range(4), 2):
            c, d = [x for x in range(4) if x not in (a, b)]
            e = p[b] - p[a]
            n1 = np.cross(e, p[c] - p[a])
            n2 = np.cross(e, p[d] - p[a])
            cos = np.dot(n1, n2) / (np.linalg.norm(n1) * np.linalg.norm(n2))
            worst = min(worst, math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    return worst


def volumes(points, tets, labels):
    out = {}
    for t, l in zip(tets, labels):
        p = points[t]
        out[l] = out.get(l, 0.0) + np.linalg.det(np.array([p[1] - p[0], p[2] - p[0], p[3] - p[0]])) / 6
    return out


class Arrays(unittest.TestCase):
    def test_smoothing_improves_and_keeps_every_subdomain_volume(self):
        points, tets, labels = jittered_grid(two_labels=True)
        mesh, report = bodt.smooth(points, tets, labels)
        self.assertIsInstance(mesh, bodt.Mesh)
        self.assertEqual(mesh.points.shape, points.shape)
        self.assertEqual(mesh.tets.shape[1], 4)
        self.assertGreater(min_dihedral_deg(mesh.points, mesh.tets), min_dihedral_deg(points, tets) + 1)
        before, after = volumes(points, tets, labels), volumes(mesh.points, mesh.tets, mesh.labels)
        self.assertEqual(sorted(before), sorted(after))
        for label in before:
            self.assertLess(abs(after[label] - before[label]) / before[label], 1e-10)
        # The report is the command line's, as a dict.
        self.assertIn(report["result"]["return_code"], ("MAX_ITERATION_NUMBER_REACHED", "CANT_IMPROVE_ANYMORE"))
        self.assertEqual(len(report["per_iteration"]), report["result"]["iterations"])
        self.assertGreater(report["result"]["moved_vertices"], 0)
        self.assertAlmostEqual(report["after"]["min_dihedral_deg"], min_dihedral_deg(mesh.points, mesh.tets), 6)
        self.assertIn("bad_tets", report["before"])

    def test_options_reach_the_pipeline(self):
        points, tets, labels = jittered_grid()
        _, report = bodt.smooth(points, tets, labels, max_iteration_number=3, method="odt", quality_guard=False,
                                largest_angle_phase=False)
        self.assertLessEqual(report["result"]["iterations"], 3)
        self.assertEqual(report["options"]["method"], "odt")
        self.assertFalse(report["options"]["quality_guard"])
        _, report = bodt.smooth(points, tets, labels, max_iteration_number=0)
        self.assertLessEqual(report["result"]["iterations"], 1000)
        if report["result"]["iterations"] < 1000:
            self.assertIn(report["result"]["return_code"], ("CONVERGENCE_REACHED", "CANT_IMPROVE_ANYMORE"))

    def test_bad_input_raises_with_the_reason(self):
        points, tets, labels = jittered_grid()
        bad = tets.copy()
        bad[5, 2] = len(points)
        with self.assertRaisesRegex(ValueError, r"tets\[5\] refers to vertex %d" % len(points)):
            bodt.smooth(points, bad, labels)
        with self.assertRaisesRegex(ValueError, "shape"):
            bodt.smooth(points[:, :2], tets)
        with self.assertRaisesRegex(ValueError, "labels"):
            bodt.smooth(points, tets, labels[:-1])
        with self.assertRaises(TypeError):
            bodt.smooth(points, tets, sliver_bound=0.01)
        flat = points.copy()
        flat[tets[0]] = flat[tets[0][0]] + np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]) * 1e-3
        with self.assertRaises(ValueError):
            bodt.smooth(flat, tets)


class Meshio(unittest.TestCase):
    def setUp(self):
        os.makedirs(TMP, exist_ok=True)

    def test_meshio_mesh_in_meshio_mesh_out_same_as_the_command_line(self):
        points, tets, labels = jittered_grid(two_labels=True)
        source = meshio.Mesh(points, [("tetra", tets)], cell_data={"medit:ref": [labels]})
        path = os.path.join(TMP, "grid.mesh")
        meshio.write(path, source)

        mesh, report = bodt.smooth(meshio.read(path))
        self.assertIsInstance(mesh, meshio.Mesh)
        self.assertEqual(len(report["per_iteration"]), report["result"]["iterations"])
        tetra = [b for b in mesh.cells if b.type == "tetra"]
        self.assertEqual(len(tetra), 1)
        np.testing.assert_array_equal(mesh.cell_data["medit:ref"][0], labels)

        # The command-line tool on the same file gives the same points, bit for bit.
        out = os.path.join(TMP, "grid-cli.mesh")
        subprocess.run([BODT_BINARY, "smooth", path, "-o", out, "--quiet"], check=True)
        cli = meshio.read(out)
        np.testing.assert_array_equal(cli.points, mesh.points)

        # And the result goes on to ParaView with its labels.
        vtu = os.path.join(TMP, "grid.vtu")
        mesh.write(vtu)
        back = meshio.read(vtu)
        np.testing.assert_array_equal(back.cell_data["medit:ref"][0], labels)


class Quality(unittest.TestCase):
    def setUp(self):
        os.makedirs(TMP, exist_ok=True)

    def test_quality_is_the_command_lines(self):
        points, tets, labels = jittered_grid(two_labels=True)
        path = os.path.join(TMP, "quality.mesh")
        meshio.write(path, meshio.Mesh(points, [("tetra", tets)], cell_data={"medit:ref": [labels]}))
        cli = json.loads(subprocess.run([BODT_BINARY, "quality", "--json", path], check=True, capture_output=True,
                                        text=True).stdout)
        self.assertEqual(bodt.quality(meshio.read(path)), cli)
        self.assertEqual(bodt.quality(points, tets, labels), cli)
        self.assertAlmostEqual(cli["min_dihedral_deg"], min_dihedral_deg(points, tets), 6)
        self.assertEqual(sorted(cli["volume_per_subdomain"]), ["1", "2"])
        # Its options, and the checks of smooth().
        self.assertEqual(len(bodt.quality(points, tets, bins=90)["histogram"]["counts"]), 90)
        self.assertIn("tets_below_30deg", bodt.quality(points, tets, small_angle=30))
        with self.assertRaises(TypeError):
            bodt.quality(points, tets, iterations=3)
        with self.assertRaisesRegex(ValueError, "bins"):
            bodt.quality(points, tets, bins=0)
        bad = tets.copy()
        bad[3, 1] = -1
        with self.assertRaisesRegex(ValueError, r"tets\[3\] refers to vertex -1"):
            bodt.quality(points, bad)


class Progress(unittest.TestCase):
    def test_progress_sees_every_sweep(self):
        points, tets, labels = jittered_grid()
        seen = []
        _, report = bodt.smooth(points, tets, labels, max_iteration_number=4, progress=seen.append)
        self.assertEqual(len(seen), report["result"]["iterations"])
        self.assertEqual(seen, report["per_iteration"])
        self.assertEqual([s["iteration"] for s in seen], list(range(1, len(seen) + 1)))

    def test_an_exception_in_progress_stops_the_run(self):
        points, tets, labels = jittered_grid()
        calls = []

        def stop_at_the_second(sweep):
            calls.append(sweep["iteration"])
            if len(calls) == 2:
                raise KeyboardInterrupt("enough")

        with self.assertRaisesRegex(KeyboardInterrupt, "enough"):
            bodt.smooth(points, tets, labels, progress=stop_at_the_second)
        self.assertEqual(calls, [1, 2])
        with self.assertRaises(TypeError):
            bodt.smooth(points, tets, labels, progress="print")


class FeatureAngles(unittest.TestCase):
    def test_angles_map_to_the_ratios(self):
        points, tets, labels = jittered_grid()
        _, report = bodt.smooth(points, tets, labels, max_iteration_number=1)
        voting = report["options"]["tensor_voting"]
        self.assertEqual((voting["edge_ratio"], voting["corner_ratio"]), (0.05, 0.05))
        # The defaults the docstring gives are those of the library's ratios.
        for name in ("feature_angle", "corner_angle"):
            documented = float(re.search(r"%s \(([0-9.]+)\)" % name, bodt.smooth.__doc__).group(1))
            self.assertAlmostEqual(documented, voting[name + "_deg"], 2)
        _, report = bodt.smooth(points, tets, labels, max_iteration_number=1, feature_angle=40, corner_angle=50)
        voting = report["options"]["tensor_voting"]
        self.assertAlmostEqual(voting["edge_ratio"], math.tan(math.radians(20)) ** 2, 15)
        self.assertAlmostEqual(voting["feature_angle_deg"], 40, 12)
        self.assertAlmostEqual(voting["corner_angle_deg"], 50, 12)
        with self.assertRaisesRegex(ValueError, "feature_angle"):
            bodt.smooth(points, tets, feature_angle=0)
        with self.assertRaisesRegex(ValueError, "corner_angle"):
            bodt.smooth(points, tets, corner_angle=91)
        with self.assertRaisesRegex(TypeError, "not both"):
            bodt.smooth(points, tets, feature_angle=30, feature_edge_ratio=0.1)


class Documentation(unittest.TestCase):
    def test_every_function_and_option_is_documented(self):
        for name in bodt.__all__:
            if callable(getattr(bodt, name)):
                self.assertGreater(len(getattr(bodt, name).__doc__ or ""), 100, name)
        for name in bodt._bodt.option_names():
            self.assertRegex(bodt.smooth.__doc__, r"\b%s\b" % name)
        self.assertIn("progress", bodt.smooth.__doc__)
        for option in ("bins", "small_angle", "large_angle", "threads"):
            self.assertIn(option, bodt.quality.__doc__)
        for field in bodt.Mesh._fields:
            self.assertTrue(getattr(bodt.Mesh, field).__doc__, field)

    def test_import_without_the_compiled_part_says_what_to_build(self):
        # The package as a checkout has it, without _bodt: PYTHONPATH=python.
        source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bodt", "__init__.py")
        folder = os.path.join(TMP, "no_compiled_part")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(os.path.join(folder, "bodt"))
        shutil.copy(source, os.path.join(folder, "bodt", "__init__.py"))
        run = subprocess.run([sys.executable, "-c", "import bodt"], capture_output=True, text=True, cwd=folder,
                             env=dict(os.environ, PYTHONPATH=folder))
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("compiled part of the module, bodt._bodt, is missing", run.stderr)
        self.assertIn("pip install --no-build-isolation .", run.stderr)
        self.assertIn("--target _bodt", run.stderr)
        self.assertNotIn("circular import", run.stderr)


if __name__ == "__main__":
    unittest.main()
