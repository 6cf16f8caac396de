// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MOVES_BOUNDARY_PROJECTION_H
#define CGAL_BODT_3_INTERNAL_MOVES_BOUNDARY_PROJECTION_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The closest point on a mesh's boundary and interface triangles as they were
/// when the projection was made: where NODT puts a boundary vertex back (CGAL's
/// AABB tree).
template <class K>
class Boundary_projection
{
public:
  using Point = typename K::Point_3;
  using Triangle = typename K::Triangle_3;

  /// The triangles between a mesh cell and a cell of another subdomain or no mesh cell.
  explicit Boundary_projection(const Flat_mesh<K>& mesh)
  {
    for(std::size_t c = 0; c < mesh.cells.size(); ++c)
    {
      if(!mesh.in_mesh[c]) continue;
      for(int i = 0; i < 4; ++i)
      {
        const int n = mesh.neighbor[4 * c + i];
        const bool boundary = n < 0 || !mesh.in_mesh[n];
        // An interface facet once, from its cell of lower index.
        const bool interface = !boundary && mesh.subdomain[n] != mesh.subdomain[c] && n > static_cast<int>(c);
        if(!boundary && !interface) continue;
        const auto& o = internal::facet_opposite[i];
        const auto& q = mesh.cells[c];
        triangles_.emplace_back(mesh.points[q[o[0]]], mesh.points[q[o[1]]], mesh.points[q[o[2]]]);
      }
    }
    if(!triangles_.empty())
    {
      tree_ = std::make_unique<Tree>(triangles_.begin(), triangles_.end());
      tree_->accelerate_distance_queries();
    }
  }

  Point operator()(const Point& p) const { return tree_ ? tree_->closest_point(p) : p; }

private:
  using Primitive = CGAL::AABB_triangle_primitive<K, typename std::vector<Triangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  std::vector<Triangle> triangles_;
  std::unique_ptr<Tree> tree_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MOVES_BOUNDARY_PROJECTION_H
