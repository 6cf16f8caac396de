// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef BODT_REPORT_MESH_PICTURES_H
#define BODT_REPORT_MESH_PICTURES_H

// Pictures of a mesh before and after smoothing, for the HTML report: the boundary
// surface seen from one direction and a cut through the mesh, each cell coloured
// by its smallest dihedral angle, the worst tetrahedra ringed and the feature
// edges drawn. Drawn by this code as inline SVG (no library, no script), so the
// page stays one file; large meshes are simplified to a bounded number of cells
// per picture, and the page says so.

#include "cli/feature_angles.h"

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Tet_mesh.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace bodt_report {

/// A plane, as a point on it and a normal (not necessarily of unit length).
struct Cut_plane
{
  std::array<double, 3> point{{0, 0, 0}};
  std::array<double, 3> normal{{0, 0, 1}};
};

/// Reads a plane written "x=V", "y=V" or "z=V" (perpendicular to that axis) or
/// "PX,PY,PZ,NX,NY,NZ" (a point and a normal). Throws std::invalid_argument
/// saying what is wrong: not numbers, not finite, a zero normal.
Cut_plane parse_cut_plane(const std::string& text);

/// Whether `plane` passes through the bounding box of the tetrahedra of `mesh`
/// (those in the mesh: labelled other than 0, unless all are 0).
bool plane_meets_mesh(const Cut_plane& plane, const CGAL::BODT_3::Tet_mesh& mesh);

/// The backgrounds of the pictures before and after, told apart in screenshots.
inline constexpr const char* picture_before_background = "#efefef";
inline constexpr const char* picture_after_background = "#e6eef8";
/// The rings around the worst tetrahedra, and the feature edges.
inline constexpr const char* worst_ring_colour = "#0033ff";
inline constexpr const char* feature_edge_colour = "#111111";

/// The colour, "#rrggbb", of a cell whose smallest dihedral angle is `degrees`:
/// dark red at 0, through orange and yellow, to green at 70.53 (the regular
/// tetrahedron) and above.
std::string quality_colour(double degrees);

/// Towards the viewer of the surface pictures (a unit vector): from +x, -y, +z.
std::array<double, 3> surface_view_direction();

struct Picture_options
{
  /// At most this many cells (triangles of the surface, polygons of the cut) per
  /// picture; beyond it, vertices closer than a grid step are merged, each drawn
  /// cell taking the worst angle of those it stands for.
  std::size_t max_cells = 2000;
  /// The worst tetrahedra ringed in each picture (the surface: the mesh's worst;
  /// the cut: the worst of those it cuts).
  std::size_t marked_worst = 10;
  /// Without feature information in the input (edges, corners, surface patches),
  /// surface edges are drawn as features where the normals of their two sides
  /// turn by more than this many degrees (the command line's --feature-angle;
  /// by default the angle of the library's default edge ratio, 25.21).
  double feature_angle = bodt_cli::angle_of_edge_ratio(CGAL::BODT_3::Tensor_voting_options().edge_ratio);
  int width = 600, height = 450;
  /// The cut; none: through the centroid of the input's worst tetrahedron,
  /// perpendicular to the surface view direction.
  std::optional<Cut_plane> cut;
  int threads = 1;   // matching faces; the pictures do not depend on it
};

/// The "The mesh" section of the report page: the surface and the cut, before and
/// after, with captions and a colour legend. `before` is the input, `after` the
/// result; both are drawn in the input's frame, so they can be compared.
std::string mesh_pictures_html(const CGAL::BODT_3::Tet_mesh& before, const CGAL::BODT_3::Tet_mesh& after,
                               const Picture_options& options = Picture_options());

} // namespace bodt_report

#endif // BODT_REPORT_MESH_PICTURES_H
