// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTH_H
#define CGAL_BODT_3_SMOOTH_H

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Smoothing_result.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/internal/Classification/Tet_mesh_constraints.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_view.h>
#include <CGAL/BODT_3/internal/Utilities/facet_surface_centers.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/internal/Mesh_optimizer.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {

namespace internal {

// The package computes constructions in doubles (its flat arrays, its moves), and
// every orientation test with CGAL's exact predicates.
template <class Tr>
constexpr void require_double_coordinates()
{
  static_assert(std::is_same<typename Tr::Geom_traits::FT, double>::value,
                "BODT_3 needs a triangulation whose geometric traits compute in double (FT = double), such as "
                "Exact_predicates_inexact_constructions_kernel or Mesh_3's default triangulation");
}

} // namespace internal

/*!
 * \ingroup PkgBODT3Functions
 * \brief Runs the pipeline (`internal::Mesh_optimizer`) on a `Mesh_complex_3_in_triangulation_3`:
 * the cells in the complex are the mesh, each subdomain keeps its volume, and the features the
 * complex knows (Mesh_3's protected curves and corners, surface patches) are kept. Flips and
 * insertion change the complex's triangulation; the facets' surface centers are set again
 * afterwards, so that CGAL's optimizers can run on the result.
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3` whose triangulation computes in `double`.
 * \tparam Visitor has `after_classification(const Smoothing_result&)` and
 *   `after_iteration(const Iteration_stats&)`.
 * \pre `c3t3.triangulation().dimension() == 3`.
 */
template <class C3T3, class Visitor = Null_smoothing_visitor>
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Smoothing_result>
smooth(C3T3& c3t3, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  internal::require_double_coordinates<typename C3T3::Triangulation>();
  internal::C3t3_adapter<C3T3> adapter(c3t3);
  auto classify = [&c3t3](const auto& view, const internal::Classification_options& opt) {
    return internal::classify_vertices(view.mesh(), internal::c3t3_feature_hints(c3t3, view), opt);
  };
  Smoothing_result result = internal::optimize_mesh(adapter, classify, options, visitor);
  // The boundary moved and its facets changed: CGAL's optimizers, run after ours, read these.
  internal::set_facet_surface_centers(c3t3);
  return result;
}

/*!
 * \ingroup PkgBODT3Functions
 * \brief Runs the pipeline on a `Triangulation_3`: its finite cells are the mesh (one subdomain),
 * its convex hull the boundary, and the hull stays convex. Features are found by tensor voting. A
 * Delaunay triangulation is in general no longer Delaunay afterwards.
 *
 * \tparam Tr a `Triangulation_3`, `Delaunay_triangulation_3` or `Regular_triangulation_3` whose
 *   geometric traits compute in `double`.
 * \pre `tr.dimension() == 3`.
 */
template <class Tr, class Visitor = Null_smoothing_visitor>
std::enable_if_t<!internal::Is_c3t3<Tr>::value && !std::is_same<Tr, Tet_mesh>::value, Smoothing_result>
smooth(Tr& tr, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  internal::require_double_coordinates<Tr>();
  internal::Triangulation_3_adapter<Tr> adapter(tr);
  const internal::Feature_hints none;
  return internal::optimize_mesh(adapter, internal::Classify_by_hints{none}, options, visitor);
}

namespace internal {

// Sheets enter the complex with their label, so that flips keep them (flips change
// a facet of the complex only for a coplanar one of the same patch, and these
// have no such neighbour across their rim); crack edges become curves, so that no
// flip changes a side of the crack. Neither is written back as such: the file's
// own triangles and edges are.
inline void add_constraints_to_complex(const Tet_mesh& tm, const Tet_mesh_constraints& constraints,
                                       const std::vector<Tet_mesh_c3t3::Vertex_handle>& handles, Tet_mesh_c3t3& c3t3)
{
  auto& tds = c3t3.triangulation().tds();
  for(std::size_t f : constraints.sheets)
  {
    const auto& t = tm.triangles[f];
    Tet_mesh_c3t3::Cell_handle c;
    int i, j, k;
    if(!tds.is_facet(handles[t[0]], handles[t[1]], handles[t[2]], c, i, j, k)) continue;
    c3t3.add_to_complex(c, 6 - i - j - k, tm.triangle_labels[f]);
    for(int v : t) c3t3.set_dimension(handles[v], 2);
  }
  int curve = 1;
  for(int l : tm.edge_labels) curve = (std::max)(curve, l + 1);
  for(const auto& e : constraints.crack_edges)
    if(!c3t3.is_in_complex(handles[e[0]], handles[e[1]])) c3t3.add_to_complex(handles[e[0]], handles[e[1]], curve);
}

// Adds what the constraints pinned to the classification the visitor is shown.
template <class Visitor>
struct Constraint_counting_visitor
{
  Visitor& visitor;
  const Tet_mesh_constraints& constraints;

  void fill(Smoothing_result& r) const
  {
    r.crack_vertices = constraints.crack_vertices;
    r.embedded_triangles = constraints.embedded_triangles;
  }
  void after_classification(const Smoothing_result& r)
  {
    Smoothing_result copy = r;
    fill(copy);
    visitor.after_classification(copy);
  }
  void after_iteration(const Iteration_stats& s) { visitor.after_iteration(s); }
};

} // namespace internal

/// The pipeline on a mesh read from a file. Tetrahedra labelled 0 are outside the
/// mesh (unless all are), but stay valid; `Edges`, `Corners`, `RequiredVertices`,
/// triangle labels and the geometry (tensor voting) together give the features
/// (`classify_vertices`). Without `Ridges`, edges labelled 0 are not features when other edges
/// are labelled (TetGen's `-e` lists every edge of the mesh, those on its segments
/// with their marker, the others with 0). Embedded surfaces and cracks are kept
/// (`Tet_mesh_constraints`). The mesh becomes a `Tet_mesh_c3t3` (tet_mesh_to_c3t3),
/// goes through the same pipeline, and comes back with `update_tet_mesh`. Its
/// infinite cells only close the mesh, so its boundary need not stay convex where
/// it is. Throws `Mesh_io_error` naming `tm.source` (the file it was read from) for
/// a mesh no triangulation can hold, leaving `tm` as it was. The tetrahedra, their
/// labels and the points are freed during the run (the complex holds them): an
/// exception after the conversion (out of memory) leaves `tm` without them.
template <class Visitor = Null_smoothing_visitor>
Smoothing_result smooth(Tet_mesh& tm, const Smoothing_options& options, Visitor&& visitor = Visitor())
{
  using K = Tet_mesh::Kernel;
  CGAL::Real_timer timer;
  timer.start();
  // The classification reads the file's own feature information.
  internal::Flat_mesh<K> flat;
  flat.threads = options.threads;
  flat.points = tm.points;
  flat.cells = tm.tets;
  const bool all_zero = tm.all_labels_zero();
  flat.in_mesh.resize(tm.tets.size());
  for(std::size_t t = 0; t < tm.tets.size(); ++t) flat.in_mesh[t] = tm.in_mesh(t, all_zero) ? 1 : 0;
  flat.subdomain = tm.tet_labels;
  // The faces are matched once, for this flat copy and for the triangulation.
  std::optional<internal::Tet_face_matching> faces(std::in_place, tm.tets, tm.points.size(), options.threads);
  flat.set_neighbors(*faces);
  flat.build_incidences();
  internal::Tet_mesh_constraints constraints = find_constraints(tm, flat);
  flat.subdomain = constraints.subdomain;

  internal::Feature_hints hints;
  const bool some_labelled = std::any_of(tm.edge_labels.begin(), tm.edge_labels.end(), [](int l) { return l != 0; });
  for(std::size_t e = 0; e < tm.edges.size(); ++e)
    if(!tm.ridges.empty() || !some_labelled || tm.edge_labels[e] != 0) hints.feature_edges.push_back(tm.edges[e]);
  hints.corners = tm.corners;
  hints.corners.insert(hints.corners.end(), tm.required_vertices.begin(), tm.required_vertices.end());
  for(std::size_t f = 0; f < tm.triangles.size(); ++f) hints.facet_patches.push_back({tm.triangles[f], tm.triangle_labels[f]});

  // Classified before the triangulation is built, so that the flat copy is gone by then.
  const double classification_start = timer.time();
  const internal::Vertex_classification by_file = internal::classify_vertices(flat, hints, internal::classification_options(options));
  flat = internal::Flat_mesh<K>();
  hints = internal::Feature_hints();
  const double classification_seconds = timer.time() - classification_start;

  Tet_mesh_c3t3 c3t3;
  std::vector<Tet_mesh_c3t3::Vertex_handle> handles;
  // The complex is built with the working labels; the file's come back at the end.
  if(constraints.relabelled) tm.tet_labels.swap(constraints.subdomain);
  tet_mesh_to_c3t3(tm, c3t3, tm.source, &handles, &*faces);
  faces.reset();
  if(constraints.relabelled) tm.tet_labels.swap(constraints.subdomain);
  internal::add_constraints_to_complex(tm, constraints, handles, c3t3);
  // The complex holds the tetrahedra, their labels and the positions now, and
  // update_tet_mesh writes them again: freed for the run, they do not add to its
  // peak memory. Only the points no tetrahedron uses (no vertex) are kept aside.
  std::vector<std::array<int, 4>>().swap(tm.tets);
  std::vector<int>().swap(tm.tet_labels);
  std::vector<int>().swap(constraints.subdomain);
  std::vector<std::pair<std::size_t, Tet_mesh::Point>> unused_points;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] == Tet_mesh_c3t3::Vertex_handle()) unused_points.emplace_back(i, tm.points[i]);
  const std::size_t file_points = tm.points.size();
  std::vector<Tet_mesh::Point>().swap(tm.points);

  internal::C3t3_adapter<Tet_mesh_c3t3> adapter(c3t3, false);
  auto classify = [&](const auto& view, const internal::Classification_options&) {
    internal::Vertex_classification classification;
    classification.kind.assign(view.vertices().size(), internal::Vertex_kind::fixed);
    classification.curve_neighbors.assign(view.vertices().size(), {-1, -1});
    classification.used_tensor_voting = by_file.used_tensor_voting;
    classification.non_manifold = by_file.non_manifold;
    for(std::size_t i = 0; i < handles.size(); ++i)
    {
      if(handles[i] == Tet_mesh_c3t3::Vertex_handle() || constraints.pinned[i]) continue;
      const int v = view.index(handles[i]);
      classification.kind[v] = by_file.kind[i];
      for(int k = 0; k < 2; ++k)
      {
        const int n = by_file.curve_neighbors[i][k];
        classification.curve_neighbors[v][k] = n >= 0 ? view.index(handles[n]) : -1;
      }
    }
    return classification;
  };
  internal::Constraint_counting_visitor<Visitor> counting{visitor, constraints};
  const double conversion = timer.time();
  Smoothing_result r = internal::optimize_mesh(adapter, classify, options, counting);
  counting.fill(r);
  const double back = timer.time();
  tm.points.resize(file_points);
  for(const auto& [i, p] : unused_points) tm.points[i] = p;
  internal::update_tet_mesh(tm, c3t3, handles, options.threads, all_zero);
  for(int& l : tm.tet_labels)
  {
    const auto it = constraints.file_label.find(l);
    if(it != constraints.file_label.end()) l = it->second;
  }
  r.phases.conversion = conversion - classification_seconds + timer.time() - back;
  r.phases.setup += classification_seconds;
  return r;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_SMOOTH_H
