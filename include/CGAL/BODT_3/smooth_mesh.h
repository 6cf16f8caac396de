// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_SMOOTH_MESH_H
#define CGAL_BODT_3_SMOOTH_MESH_H

#include <CGAL/BODT_3/Move_guard.h>
#include <CGAL/BODT_3/Smoothing_mesh.h>
#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/Tensor_voting.h>
#include <CGAL/BODT_3/Vertex_classification.h>
#include <CGAL/BODT_3/Volume_preserving_move.h>
#include <CGAL/BODT_3/sweep_order.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace BODT_3 {

/// The smoothing driver: classifies the vertices once, then runs sweeps in which
/// every movable vertex, in `sweep_order`, gets its volume-preserving B-ODT move
/// (`Volume_preserving_move`) through `Move_guard`. It stops after
/// `max_iteration_number` sweeps, at the time limit, at convergence, or when a
/// sweep moves nothing.
template <class K, class Visitor = Null_smoothing_visitor>
Smoothing_result smooth_mesh(Smoothing_mesh<K>& mesh, const Feature_hints& hints, const Smoothing_options& opt,
                             Visitor&& visitor = Visitor())
{
  using Vector = typename K::Vector_3;
  CGAL::Real_timer timer;
  timer.start();

  Classification_options copt;
  copt.move_boundary = opt.moving_vertices == Moving_vertices::ALL;
  copt.preserve_features = opt.preserve_features;
  copt.tensor_voting = opt.tensor_voting;
  const Vertex_classification cls = classify_vertices(mesh, hints, copt);

  Smoothing_result result;
  result.interior_vertices = cls.count(Vertex_kind::interior);
  result.surface_vertices = cls.count(Vertex_kind::surface);
  result.feature_vertices = cls.count(Vertex_kind::feature);
  result.fixed_vertices = cls.count(Vertex_kind::fixed);
  result.non_manifold_vertices = cls.non_manifold;
  result.used_tensor_voting = cls.used_tensor_voting;
  visitor.after_classification(result);

  std::vector<char> movable(mesh.number_of_vertices());
  for(std::size_t v = 0; v < movable.size(); ++v) movable[v] = cls.kind[v] != Vertex_kind::fixed;
  const Sweep_order order = sweep_order(mesh, movable);

  // A vertex whose last move was zero or refused gets the same verdict again until
  // a vertex its move depends on (its star, or the far vertex of one of its hull
  // checks) moves: such vertices are skipped, which changes no result.
  std::vector<std::vector<int>> dependents(mesh.number_of_vertices());
  for(int v : order.vertices)
  {
    for(int k = mesh.incidence_begin[v]; k < mesh.incidence_begin[v + 1]; ++k)
      for(int u : mesh.incidences[k].face) dependents[u].push_back(v);
    for(int k = mesh.hull_begin[v]; k < mesh.hull_begin[v + 1]; ++k)
      dependents[mesh.vertex_hull_checks[k][3]].push_back(v);
  }
  for(auto& d : dependents)
  {
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
  }
  std::vector<char> dirty(mesh.number_of_vertices(), 1);

  Move_guard<K> guard(mesh, opt.quality_guard);
  const Volume_preserving_move mover;
  Vertex_star<K> star;
  std::vector<char> moved_once(mesh.number_of_vertices(), 0);
  result.code = MAX_ITERATION_NUMBER_REACHED;

  for(std::size_t it = 1; it <= (opt.max_iteration_number == 0 ? 1000 : opt.max_iteration_number); ++it)   // 0: CGAL's cap
  {
    Iteration_stats stats;
    stats.iteration = it;
    for(int v : order.vertices)
    {
      if(!dirty[v]) continue;
      dirty[v] = 0;
      const Vertex_kind kind = cls.kind[v];
      mesh.gather_star(v, star);
      Vector direction(0, 0, 0);
      if(kind == Vertex_kind::feature)
      {
        const auto& nb = cls.curve_neighbors[v];
        direction = nb[0] >= 0 ? mesh.points[nb[1]] - mesh.points[nb[0]]
                               : tensor_vote(star, opt.tensor_voting).direction;
      }
      const Vector X = mover(star, kind, direction);
      if(X == CGAL::NULL_VECTOR) continue;
      const double fraction = guard.move(v, X);
      if(fraction == 0)
      {
        ++stats.refused;
        using Refusal = typename Move_guard<K>::Refusal;
        switch(guard.first_refusal())
        {
        case Refusal::inverts_mesh_cell: ++stats.refused_inverting_mesh_cell; break;
        case Refusal::inverts_outside_cell: ++stats.refused_inverting_outside_cell; break;
        case Refusal::breaks_convex_hull: ++stats.refused_breaking_hull; break;
        case Refusal::worsens_quality: ++stats.refused_worsening_quality; break;
        }
        continue;
      }
      ++stats.moved;
      if(fraction < 1) ++stats.shortened;
      moved_once[v] = 1;
      dirty[v] = 1;
      for(int u : dependents[v]) dirty[u] = 1;
      double volume = 0;
      for(const auto& c : star.cells) volume += CGAL::determinant(c.a - star.x0, c.b - star.x0, c.c - star.x0);
      const double size = std::cbrt(volume / 6.0 / static_cast<double>(star.cells.size()));
      stats.max_relative_move = std::max(stats.max_relative_move, fraction * std::sqrt(X.squared_length()) / size);
    }
    stats.seconds = timer.time();
    result.iterations = it;
    visitor.after_iteration(stats);
    if(stats.moved == 0) { result.code = CANT_IMPROVE_ANYMORE; break; }
    if(opt.convergence > 0 && stats.max_relative_move < opt.convergence) { result.code = CONVERGENCE_REACHED; break; }
    if(opt.time_limit > 0 && timer.time() >= opt.time_limit) { result.code = TIME_LIMIT_REACHED; break; }
  }
  for(char m : moved_once) result.moved_vertices += static_cast<std::size_t>(m);
  result.seconds = timer.time();
  return result;
}

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_SMOOTH_MESH_H
