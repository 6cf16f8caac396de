// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test and benchmark inputs built with CGAL's Mesh_3, deterministic, so that a
// fresh clone needs no mesh file. Only generated_inputs.cpp instantiates
// make_mesh_3; everything else includes this header for the types.
#ifndef BODT_GENERATED_INPUTS_H
#define BODT_GENERATED_INPUTS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <memory>
#include <string>
#include <vector>

namespace bodt_inputs {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Labeled_domain = CGAL::Labeled_mesh_domain_3<K>;
using Mesh_domain = CGAL::Mesh_domain_with_polyline_features_3<Labeled_domain>;
using Tr = CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index,
                                                     Mesh_domain::Curve_index>;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;
using Polyline = std::vector<Point>;

enum class Shape
{
  sphere,          // unit ball
  torus,           // ring torus, R = 1, r = 0.4
  genus2,          // a solid with two handles
  sharp_part,      // an L-shaped block with a chamfer: straight sharp edges, corners, protected
  two_subdomains   // unit ball cut by the plane z = 0: label 1 below, 2 above, junction protected
};

enum class Size
{
  small,       // a few thousand tetrahedra, for tests
  benchmark    // about 40,000 tetrahedra
};

std::vector<Shape> all_shapes();
std::string name(Shape shape);

/// A Mesh_3 output: the raw refinement result (no perturbation, no exudation),
/// with the domain kept so that CGAL's own optimizers can be run on it.
struct Generated_mesh
{
  std::string name;
  std::shared_ptr<Mesh_domain> domain;
  C3t3 c3t3;
};

/// Meshes `shape` at `size` with make_mesh_3. Same arguments, same mesh.
/// `refinement` divides the size criteria (and the facet distance by its square),
/// so that the mesh has about `refinement`^3 times as many cells (scale benchmark).
Generated_mesh make_input(Shape shape, Size size, double refinement = 1.0);

/// The feature polylines given to Mesh_3 for `shape` (empty for smooth shapes);
/// for the sharp part they are exact straight edges.
std::vector<Polyline> feature_polylines(Shape shape);

/// The paper's "random sphere": `n` random points on the unit sphere (seeded,
/// reproducible), tetrahedralized by Delaunay_triangulation_3. The default `n` is
/// the paper's 642; `Size::benchmark` uses as many points as give about 40,000 cells.
Delaunay make_random_sphere(std::size_t n = 642, unsigned seed = 1);
Delaunay make_random_sphere(Size size);

/// The paper's Random Sphere as the paper describes it (642 random points on the
/// unit sphere and inner vertices, Delaunay, then sliver removal): 642 seeded random
/// points on the unit sphere and 87 in the ball of radius 0.8, then a seeded sliver
/// removal of ours (random moves of the worst cell's vertices, surface points kept
/// on the sphere, each kept if fewer cells are left under the bound) until no
/// dihedral angle is below the paper's input's 5.86 degrees, and the Delaunay
/// triangulation of the moved points. CGAL's perturb_mesh_3 did this before, but
/// took seconds to minutes from run to run. The unit-ball domain is kept, so CGAL's
/// optimizers apply. Same seed, same mesh.
Generated_mesh make_paper_random_sphere(unsigned seed = 1);

} // namespace bodt_inputs

#endif // BODT_GENERATED_INPUTS_H
