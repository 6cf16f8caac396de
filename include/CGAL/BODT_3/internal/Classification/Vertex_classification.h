// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_CLASSIFICATION_VERTEX_CLASSIFICATION_H
#define CGAL_BODT_3_INTERNAL_CLASSIFICATION_VERTEX_CLASSIFICATION_H

#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Classification/Tensor_voting.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Utilities/id_keys.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// How a vertex may move.
enum class Vertex_kind : unsigned char
{
  fixed,      // corners, non-manifold points, vertices of no mesh cell, or not allowed to move
  interior,   // inside one subdomain: ODT (Algorithm 1)
  surface,    // on the boundary or on an interface: basic B-ODT (Algorithm 2)
  feature     // on a feature curve: advanced B-ODT (Algorithm 3)
};

/// What the input knows about its features. Every member may stay empty.
struct Feature_hints
{
  /// Per vertex, Mesh_3's dimension (3 interior, 2 surface, 1 curve, 0 corner),
  /// or -1 where unknown.
  std::vector<signed char> dimension;
  /// Feature edges (vertex pairs): Mesh_3 curve edges, or a file's `Edges`.
  std::vector<std::array<int, 2>> feature_edges;
  /// Vertices that must not move: Mesh_3 corners, a file's `Corners` and `RequiredVertices`.
  std::vector<int> corners;
  /// Surface patch of boundary and interface facets (sorted vertex triple -> label).
  std::vector<std::pair<std::array<int, 3>, int>> facet_patches;
};

struct Classification_options
{
  bool move_boundary = true;        // false: only interior vertices move (the ODT baseline)
  bool preserve_features = true;    // false: every boundary vertex uses Algorithm 2
  Tensor_voting_options tensor_voting;
};

/// The result: a kind per vertex, and for feature vertices whose curve is known,
/// its two neighbours along the curve (-1 when the direction comes from tensor voting).
struct Vertex_classification
{
  std::vector<Vertex_kind> kind;
  std::vector<std::array<int, 2>> curve_neighbors;
  bool used_tensor_voting = false;
  std::size_t non_manifold = 0;

  std::size_t count(Vertex_kind k) const { return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k)); }
};


// Whether oriented facets (x0, a, b) around x0 form exactly one closed cycle.
inline bool is_one_cycle(const std::vector<std::array<int, 2>>& facets)
{
  if(facets.empty()) return true;
  std::unordered_map<int, int> next;
  for(const auto& f : facets)
    if(!next.emplace(f[0], f[1]).second) return false;
  // Following the cycle from one facet must visit every facet before coming back.
  const int start = facets.front()[0];
  int v = start;
  for(std::size_t steps = 1; steps <= facets.size(); ++steps)
  {
    auto it = next.find(v);
    if(it == next.end()) return false;
    v = it->second;
    if(v == start) return steps == facets.size();
  }
  return false;
}

// The surface facets of a mesh are those between a mesh cell and the outside or a
// cell of another subdomain. Each has a patch: the hints' label of the facet (or
// none) together with the pair of subdomains it separates, so that one label on two
// surfaces (a file giving the outer boundary and an interface the same ref, or the
// outer boundary on both sides of an interface) still makes two patches, and the
// rim where they meet is a junction. Returns the edges of surface facets around
// which the facets (each interface facet seen from both its cells) are of two
// patches or more, in the order of a hash map of all of them.
template <class K>
std::vector<std::pair<int, int>> junction_edges(const Flat_mesh<K>& mesh, const Feature_hints& hints)
{
  std::unordered_map<std::array<int, 3>, int, Id_hash> label;
  for(const auto& fp : hints.facet_patches) label.emplace(sorted(fp.first), fp.second);
  constexpr int unlabelled = (std::numeric_limits<int>::min)();
  std::map<std::array<int, 3>, int> patch_of;   // (label, subdomain, subdomain) -> patch
  // The surface facets (4 c + i), found in parallel blocks, then the map in their order.
  auto outside = [&](int n) { return n < 0 || !mesh.in_mesh[n]; };
  const std::vector<std::size_t> surface =
      Thread_workers<char>(mesh.threads).indices_where(4 * mesh.cells.size(), [&](std::size_t f) {
        const std::size_t c = f / 4;
        const int n = mesh.neighbor[f];
        return mesh.in_mesh[c] && (outside(n) || mesh.subdomain[n] != mesh.subdomain[c]);
      });
  // Per edge, its first patch and whether another one meets it.
  struct Patches
  {
    int first = -1;
    bool several = false;
  };
  std::unordered_map<std::pair<int, int>, Patches, Id_hash> around;
  for(const std::size_t facet : surface)
  {
    const int c = static_cast<int>(facet / 4), i = static_cast<int>(facet % 4);
    const int n = mesh.neighbor[facet];
    const auto& o = facet_opposite[i];
    const std::array<int, 3> f = {mesh.cells[c][o[0]], mesh.cells[c][o[1]], mesh.cells[c][o[2]]};
    const auto it = label.find(sorted(f));
    const int s0 = mesh.subdomain[c], s1 = outside(n) ? 0 : mesh.subdomain[n];
    const std::array<int, 3> key = {it != label.end() ? it->second : unlabelled, (std::min)(s0, s1),
                                    (std::max)(s0, s1)};
    const int patch = patch_of.emplace(key, static_cast<int>(patch_of.size())).first->second;
    for(int k = 0; k < 3; ++k)
    {
      Patches& p = around[edge_key(f[k], f[(k + 1) % 3])];
      if(p.first < 0) p.first = patch;
      else if(p.first != patch) p.several = true;
    }
  }
  std::vector<std::pair<int, int>> out;
  for(const auto& [edge, patches] : around)
    if(patches.several) out.push_back(edge);
  return out;
}

// Calls `f(a, b)` for each surface facet through `v`, once (an interface facet from
// the cell of the smaller subdomain), (v, a, b) oriented out of that cell; the
// boundary facets come in the order of `Flat_mesh::gather_star`.
template <class K, class F>
void for_each_surface_facet(const Flat_mesh<K>& mesh, int v, const F& f)
{
  for(int k = mesh.incidence_begin[v]; k < mesh.incidence_begin[v + 1]; ++k)
  {
    const int c = mesh.incidences[k].cell;
    if(!mesh.in_mesh[c]) continue;
    for(int i = 0; i < 4; ++i)
    {
      const int n = mesh.neighbor[4 * c + i];
      if(mesh.cells[c][i] == v || (n >= 0 && mesh.in_mesh[n] && mesh.subdomain[n] <= mesh.subdomain[c])) continue;
      const auto& o = facet_opposite[i];
      const int t[3] = {mesh.cells[c][o[0]], mesh.cells[c][o[1]], mesh.cells[c][o[2]]};
      for(int j = 0; j < 3; ++j)
        if(t[j] == v) f(t[(j + 1) % 3], t[(j + 2) % 3]);
    }
  }
}

// The star tensor voting reads: the surface facets through `v`.
template <class K>
void gather_surface_star(const Flat_mesh<K>& mesh, int v, Vertex_star<K>& star)
{
  star.clear();
  star.x0 = mesh.points[v];
  for_each_surface_facet(mesh, v, [&](int a, int b) { star.boundary.push_back({mesh.points[a], mesh.points[b]}); });
}

// The neighbours along its edge of a vertex `v` that voted for one: among the
// vertices of its surface facets that voted for an edge or a corner, the one most
// nearly along the voted direction and the one most nearly against it, each within
// about 25 degrees of it; {-1, -1} when either is missing.
template <class K>
std::array<int, 2> voted_edge_neighbors(const Flat_mesh<K>& mesh, const std::vector<Tensor_vote<K>>& vote, int v)
{
  const auto& d = vote[v].direction;
  std::array<int, 2> best = {-1, -1};
  std::array<double, 2> cosine = {0.9, 0.9};   // cos(25.8 degrees), as for a crossing in rule 5
  for_each_surface_facet(mesh, v, [&](int a, int b) {
    for(int w : {a, b})
    {
      if(vote[w].kind == Voted_kind::surface) continue;
      const auto e = mesh.points[w] - mesh.points[v];
      const double c = (e * d) / std::sqrt(e.squared_length() * d.squared_length());
      for(int side = 0; side < 2; ++side)
        if((side == 0 ? c : -c) > cosine[side])
        {
          cosine[side] = side == 0 ? c : -c;
          best[side] = w;
        }
    }
  });
  if(best[0] < 0 || best[1] < 0) return {-1, -1};
  return best;
}

/// Classifies every vertex of `mesh` (see `Vertex_kind`). A vertex is a corner, or on
/// a feature curve, if any source says so. The rules, in order:
/// 1. A vertex of no mesh cell is fixed; so is every non-interior vertex when only
///    interior vertices move.
/// 2. For each subdomain around the vertex, the boundary of that subdomain's part
///    of the star must be one closed cycle of triangles; otherwise (a non-manifold
///    point) the vertex is fixed.
/// 3. Inside one subdomain, with no boundary facet: interior, unless the hints say
///    it lies on a feature.
/// 4. With feature preservation on, feature edges are the hints' edges and the
///    edges where facets of two or more surface patches meet (`junction_edges`: a
///    patch is a facet's label and the pair of subdomains it separates, so interfaces
///    and their rims on the boundary are features). A vertex on exactly two feature
///    edges lies on a feature curve; on one, or three and more, or two that turn by
///    more than 60 degrees, it is a corner; so is a vertex the hints call a corner.
/// 5. The geometry, where the input has no dimensions of its own (a file, a
///    `Triangulation_3`; a C3T3's dimensions come from the domain Mesh_3 meshed):
///    tensor voting (eq. 11) over the boundary and interface facets around each
///    vertex. A vote for a corner makes a corner. On a feature curve of rule 4, a
///    vote for an edge across the curve (their directions more than about 25
///    degrees apart) makes a corner: a sharp edge ends there. Elsewhere a vote for
///    an edge makes a feature vertex that moves along the voted direction (the sweep
///    votes again as the vertex moves); off the outer boundary (an edge of an
///    interface) it moves along the chord between its two neighbours on the edge,
///    the vertices of its facets that voted for an edge or a corner and lie most
///    nearly along the voted direction on either side, and is fixed when there are no
///    such two.
/// 6. Every other vertex is a surface vertex.
template <class K>
Vertex_classification classify_vertices(const Flat_mesh<K>& mesh, const Feature_hints& hints,
                                        const Classification_options& opt)
{
  using Vector = typename K::Vector_3;
  const int nv = static_cast<int>(mesh.number_of_vertices());
  Vertex_classification out;
  out.kind.assign(nv, Vertex_kind::fixed);
  out.curve_neighbors.assign(nv, {-1, -1});

  const bool hints_dims = std::any_of(hints.dimension.begin(), hints.dimension.end(),
                                      [](signed char d) { return d >= 0; });
  out.used_tensor_voting = opt.preserve_features && opt.move_boundary && !hints_dims;

  // Feature edges and the feature degree of each vertex.
  std::unordered_set<std::pair<int, int>, internal::Id_hash> feature_edges;
  if(opt.preserve_features)
  {
    for(const auto& e : hints.feature_edges)
      if(e[0] != e[1]) feature_edges.insert(internal::edge_key(e[0], e[1]));
    for(const auto& e : internal::junction_edges(mesh, hints)) feature_edges.insert(e);
  }
  std::vector<std::vector<int>> feature_nbrs(nv);
  for(const auto& e : feature_edges)
  {
    feature_nbrs[e.first].push_back(e.second);
    feature_nbrs[e.second].push_back(e.first);
  }
  std::vector<char> is_corner(nv, 0);
  if(opt.preserve_features)
    for(int v : hints.corners)
      if(v >= 0 && v < nv) is_corner[v] = 1;

  // Rule 5's votes, first for every vertex on a surface, since an interface vertex
  // looks for its neighbours on the edge among the others' votes. Vertices are
  // independent: classified in parallel (`mesh.threads`).
  struct Worker
  {
    Vertex_star<K> star;
    std::size_t non_manifold = 0;
  };
  Thread_workers<Worker> workers(mesh.threads);
  std::vector<Tensor_vote<K>> vote(out.used_tensor_voting ? nv : 0, Tensor_vote<K>{Voted_kind::surface, Vector(0, 0, 0)});
  if(out.used_tensor_voting)
    workers.for_each(0, nv, [&](Worker& w, int v) {
      internal::gather_surface_star(mesh, v, w.star);
      if(!w.star.boundary.empty()) vote[v] = tensor_vote(w.star, opt.tensor_voting);
    }, 256);

  workers.for_each(0, nv, [&](Worker& w, int v) {
    // Subdomains around v, and the boundary of each one's part of the star.
    std::map<int, std::vector<std::array<int, 2>>> side_boundary;
    for(int k = mesh.incidence_begin[v]; k < mesh.incidence_begin[v + 1]; ++k)
    {
      const int c = mesh.incidences[k].cell;
      if(!mesh.in_mesh[c]) continue;
      auto& facets = side_boundary[mesh.subdomain[c]];
      for(int i = 0; i < 4; ++i)
      {
        if(mesh.cells[c][i] == v) continue;
        const int n = mesh.neighbor[4 * c + i];
        if(n >= 0 && mesh.in_mesh[n] && mesh.subdomain[n] == mesh.subdomain[c]) continue;
        const auto& o = internal::facet_opposite[i];
        const int f[3] = {mesh.cells[c][o[0]], mesh.cells[c][o[1]], mesh.cells[c][o[2]]};
        for(int j = 0; j < 3; ++j)
          if(f[j] == v) facets.push_back({f[(j + 1) % 3], f[(j + 2) % 3]});
      }
    }
    if(side_boundary.empty()) return;                            // rule 1
    const bool interior = side_boundary.size() == 1 && side_boundary.begin()->second.empty();
    if(!interior && !opt.move_boundary) return;
    bool manifold = true;
    for(const auto& side : side_boundary) manifold = manifold && internal::is_one_cycle(side.second);
    if(!manifold)                                                // rule 2
    {
      ++w.non_manifold;
      return;
    }

    const signed char dim = v < static_cast<int>(hints.dimension.size()) ? hints.dimension[v] : -1;
    Vertex_kind kind = interior ? Vertex_kind::interior : Vertex_kind::surface;
    if(opt.preserve_features)
    {
      const std::size_t degree = feature_nbrs[v].size();
      const Tensor_vote<K> voted = vote.empty() ? Tensor_vote<K>{Voted_kind::surface, Vector(0, 0, 0)} : vote[v];
      // Two feature edges make a curve point only if the curve goes on: a turn of
      // more than 60 degrees (or a crossing with a voted edge) is a corner.
      bool curve_point = false;
      if(degree == 2)
      {
        const auto u = mesh.points[feature_nbrs[v][0]] - mesh.points[v];
        const auto x = mesh.points[feature_nbrs[v][1]] - mesh.points[v];
        curve_point = u * x < -0.5 * std::sqrt(u.squared_length() * x.squared_length());
        if(curve_point && voted.kind == Voted_kind::feature)
        {
          const auto chord = x - u;
          curve_point = std::abs(chord * voted.direction) >=
                        0.9 * std::sqrt(chord.squared_length() * voted.direction.squared_length());
        }
      }
      if(is_corner[v] || dim == 0 || voted.kind == Voted_kind::corner || (degree > 0 && !curve_point))
        kind = Vertex_kind::fixed;
      else if(degree == 2)
      {
        kind = Vertex_kind::feature;
        out.curve_neighbors[v] = {feature_nbrs[v][0], feature_nbrs[v][1]};
      }
      else if(dim == 1)
        kind = Vertex_kind::fixed;                               // a curve vertex whose curve is unknown
      else if(voted.kind == Voted_kind::feature)
      {
        kind = Vertex_kind::feature;
        if(mesh.boundary_begin[v + 1] == mesh.boundary_begin[v])
        {
          // The sweep votes over the outer boundary only: an interface vertex needs
          // its neighbours on the edge.
          out.curve_neighbors[v] = internal::voted_edge_neighbors(mesh, vote, v);
          if(out.curve_neighbors[v][0] < 0) kind = Vertex_kind::fixed;
        }
      }
    }
    out.kind[v] = kind;
  }, 256);
  workers.each_worker([&out](const Worker& w) { out.non_manifold += w.non_manifold; });
  return out;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_CLASSIFICATION_VERTEX_CLASSIFICATION_H
