// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_INSERTION_BAD_TET_SHAPE_H
#define CGAL_BODT_3_INTERNAL_INSERTION_BAD_TET_SHAPE_H

#include <CGAL/BODT_3/Smoothing_options.h>
#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The shapes of bad tetrahedra (Cheng et al. 1999, the paper's Fig. 2). Six of
/// them have short edges, which smoothing lengthens; spades, caps and slivers have
/// none, and the paper splits them (Sec. 2.3).
enum class Bad_tet_shape : unsigned char
{
  good,       // no dihedral angle out of bounds
  wedge,      // one short edge, over the middle of the opposite edge
  spike,      // one short edge, beyond an end of the opposite edge
  spear,      // two short edges sharing a vertex, bent there
  spindle,    // two opposite short edges
  spire,      // three short edges around a face: three close vertices and a far one
  splinter,   // two short edges sharing a vertex, nearly in line
  spade,      // no short edge; a vertex close to an edge of its opposite face
  cap,        // no short edge; a vertex close to the inside of its opposite face
  sliver,     // no short edge; two opposite edges close to crossing
  other       // bad, with none of these patterns within the thresholds
};

constexpr std::size_t number_of_bad_tet_shapes = 11;

inline const char* name(Bad_tet_shape s)
{
  switch(s)
  {
  case Bad_tet_shape::good: return "good";
  case Bad_tet_shape::wedge: return "wedge";
  case Bad_tet_shape::spike: return "spike";
  case Bad_tet_shape::spear: return "spear";
  case Bad_tet_shape::spindle: return "spindle";
  case Bad_tet_shape::spire: return "spire";
  case Bad_tet_shape::splinter: return "splinter";
  case Bad_tet_shape::spade: return "spade";
  case Bad_tet_shape::cap: return "cap";
  case Bad_tet_shape::sliver: return "sliver";
  case Bad_tet_shape::other: return "other";
  }
  return "";
}

/// A classified tetrahedron (p0, p1, p2, p3), with where to split it:
///  - spade: `vertex` is close to edge (`edge[0]`, `edge[1]`), to be split at
///    `t[0]` (the parameter along the edge of the projection of `vertex`);
///  - cap: `vertex` is close to the inside of its opposite face, to be split at
///    barycentric coordinates `bary` (of the face's vertices in increasing order);
///  - sliver: edges (`edge[0]`, `edge[1]`) and (`edge[2]`, `edge[3]`) come closest
///    at parameters `t[0]` and `t[1]`;
///  - the others: `edge` lists the short edges' endpoints, two by two.
struct Bad_tet
{
  Bad_tet_shape shape = Bad_tet_shape::good;
  int vertex = -1;
  std::array<int, 6> edge = {-1, -1, -1, -1, -1, -1};
  std::array<double, 2> t = {0, 0};
  std::array<double, 3> bary = {0, 0, 0};
};


struct V3
{
  double x, y, z;
};
inline V3 sub(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}


/// Classifies a tetrahedron by its dihedral angles (bad or not) and, when bad, by
/// its short edges and, without them, by where its vertices project:
///  1. an edge is short if shorter than `short_edge` times the longest. By the
///     triangle inequality (with `short_edge` below 1/3), short edges never chain
///     between the ends of the longest edge, so there are at most three, around a
///     face, and: one is a wedge or a spike (the short edge's midpoint projecting
///     inside the opposite edge, or not), two sharing a vertex a splinter if they
///     are nearly in line (more than 120 degrees apart) and a spear otherwise, two
///     opposite a spindle, three (around a face) a spire;
///  2. with no short edge, the tetrahedron is flat: if a vertex projects inside its
///     opposite face (every barycentric coordinate above `margin`), it is a cap
///     (the vertex nearest its face wins); else if a vertex projects inside an edge
///     of its opposite face, nearer that edge than the other vertices are to theirs,
///     a spade; else if two opposite edges have their closest points inside both, a
///     sliver (the closest pair wins); else `other`.
template <class Point>
Bad_tet classify_bad_tet(const Point& p0, const Point& p1, const Point& p2, const Point& p3,
                         const Bad_tet_options& opt = Bad_tet_options())
{
  using internal::V3;
  Bad_tet out;
  const auto angles = dihedral_angles(p0, p1, p2, p3);
  const auto mm = std::minmax_element(angles.begin(), angles.end());
  if(*mm.first >= opt.small_angle && *mm.second <= opt.large_angle) return out;

  const V3 p[4] = {{p0.x(), p0.y(), p0.z()}, {p1.x(), p1.y(), p1.z()}, {p2.x(), p2.y(), p2.z()},
                   {p3.x(), p3.y(), p3.z()}};
  static const int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  double len2[6], longest2 = 0;
  for(int e = 0; e < 6; ++e)
  {
    const V3 d = internal::sub(p[edges[e][1]], p[edges[e][0]]);
    len2[e] = internal::dot(d, d);
    longest2 = std::max(longest2, len2[e]);
  }
  int shorts[6], n = 0;
  for(int e = 0; e < 6; ++e)
    if(len2[e] < opt.short_edge * opt.short_edge * longest2) shorts[n++] = e;
  for(int k = 0; k < n; ++k)
  {
    out.edge[2 * k] = edges[shorts[k]][0];
    out.edge[2 * k + 1] = edges[shorts[k]][1];
  }
  auto shares = [&](int e, int f) {
    return edges[e][0] == edges[f][0] || edges[e][0] == edges[f][1] || edges[e][1] == edges[f][0] ||
           edges[e][1] == edges[f][1];
  };
  if(n == 1)
  {
    // The opposite edge (c, d) and the short edge's midpoint m: where m projects on c d.
    const int a = edges[shorts[0]][0], b = edges[shorts[0]][1];
    int cd[2], m = 0;
    for(int v = 0; v < 4; ++v)
      if(v != a && v != b) cd[m++] = v;
    const V3 mid = {(p[a].x + p[b].x) / 2, (p[a].y + p[b].y) / 2, (p[a].z + p[b].z) / 2};
    const V3 u = internal::sub(p[cd[1]], p[cd[0]]);
    const double s = internal::dot(internal::sub(mid, p[cd[0]]), u) / internal::dot(u, u);
    out.shape = s > 0 && s < 1 ? Bad_tet_shape::wedge : Bad_tet_shape::spike;
    return out;
  }
  if(n == 2)
  {
    if(!shares(shorts[0], shorts[1]))
    {
      out.shape = Bad_tet_shape::spindle;
      return out;
    }
    // The shared vertex b and the two far ends: in line (a splinter) or bent (a spear).
    const int e = shorts[0], f = shorts[1];
    const int b = edges[e][0] == edges[f][0] || edges[e][0] == edges[f][1] ? edges[e][0] : edges[e][1];
    const int a = edges[e][0] == b ? edges[e][1] : edges[e][0];
    const int c = edges[f][0] == b ? edges[f][1] : edges[f][0];
    const V3 u = internal::sub(p[a], p[b]), w = internal::sub(p[c], p[b]);
    const bool in_line = internal::dot(u, w) < -0.5 * std::sqrt(internal::dot(u, u) * internal::dot(w, w));
    out.shape = in_line ? Bad_tet_shape::splinter : Bad_tet_shape::spear;
    return out;
  }
  if(n == 3)
  {
    out.shape = Bad_tet_shape::spire;
    return out;
  }

  // Flat, no short edge. Cap: a vertex projecting inside its opposite face.
  double best = -1;
  for(int v = 0; v < 4; ++v)
  {
    int f[3], m = 0;
    for(int k = 0; k < 4; ++k)
      if(k != v) f[m++] = k;
    const V3 nrm = internal::cross(internal::sub(p[f[1]], p[f[0]]), internal::sub(p[f[2]], p[f[0]]));
    const double n2 = internal::dot(nrm, nrm);
    if(!(n2 > 0)) continue;
    double bary[3];
    for(int k = 0; k < 3; ++k)
    {
      // The signed area of the sub-triangle opposite f[k], with p[v] in place of f[k].
      const V3& b = p[f[(k + 1) % 3]];
      const V3& c = p[f[(k + 2) % 3]];
      bary[k] = internal::dot(internal::cross(internal::sub(b, p[v]), internal::sub(c, p[v])), nrm) / n2;
    }
    if(std::min({bary[0], bary[1], bary[2]}) <= opt.margin) continue;
    // Nearest to its face, relative to the face's size: height^2 / area.
    const double h = internal::dot(internal::sub(p[v], p[f[0]]), nrm);
    const double closeness = n2 * std::sqrt(n2) / (h * h + 1e-300);
    if(closeness > best)
    {
      best = closeness;
      out.shape = Bad_tet_shape::cap;
      out.vertex = v;
      out.bary = {bary[0], bary[1], bary[2]};
    }
  }
  if(out.shape == Bad_tet_shape::cap) return out;

  // Spade: a vertex projecting inside an edge of its opposite face, nearest first.
  double nearest = -1;
  for(int v = 0; v < 4; ++v)
    for(int e = 0; e < 6; ++e)
    {
      const int a = edges[e][0], b = edges[e][1];
      if(a == v || b == v) continue;
      const V3 u = internal::sub(p[b], p[a]);
      const double s = internal::dot(internal::sub(p[v], p[a]), u) / internal::dot(u, u);
      if(!(s > opt.margin && s < 1 - opt.margin)) continue;
      const V3 foot = {p[a].x + s * u.x, p[a].y + s * u.y, p[a].z + s * u.z};
      const V3 d = internal::sub(p[v], foot);
      const double dist2 = internal::dot(d, d) / internal::dot(u, u);
      if(nearest < 0 || dist2 < nearest)
      {
        nearest = dist2;
        out.vertex = v;
        out.edge[0] = a;
        out.edge[1] = b;
        out.t[0] = s;
      }
    }
  // A spade's vertex lies nearer its edge than the opposite edges come to crossing.
  double crossing = -1;
  Bad_tet sliver;
  static const int opposite[3][2] = {{0, 5}, {1, 4}, {2, 3}};
  for(const auto& pair : opposite)
  {
    const int a = edges[pair[0]][0], b = edges[pair[0]][1], c = edges[pair[1]][0], d = edges[pair[1]][1];
    const V3 u = internal::sub(p[b], p[a]), w = internal::sub(p[d], p[c]), r = internal::sub(p[a], p[c]);
    const double uu = internal::dot(u, u), uw = internal::dot(u, w), ww = internal::dot(w, w);
    const double ur = internal::dot(u, r), wr = internal::dot(w, r);
    const double den = uu * ww - uw * uw;
    if(!(den > 0)) continue;
    const double s = (uw * wr - ww * ur) / den, t = (uu * wr - uw * ur) / den;
    if(!(s > opt.margin && s < 1 - opt.margin && t > opt.margin && t < 1 - opt.margin)) continue;
    const V3 gap = {r.x + s * u.x - t * w.x, r.y + s * u.y - t * w.y, r.z + s * u.z - t * w.z};
    const double dist2 = internal::dot(gap, gap) / std::max(uu, ww);
    if(crossing < 0 || dist2 < crossing)
    {
      crossing = dist2;
      sliver.shape = Bad_tet_shape::sliver;
      sliver.edge = {a, b, c, d, -1, -1};
      sliver.t = {s, t};
    }
  }
  if(nearest >= 0 && (crossing < 0 || nearest <= crossing))
  {
    out.shape = Bad_tet_shape::spade;
    return out;
  }
  if(crossing >= 0) return sliver;
  out.shape = Bad_tet_shape::other;
  out.vertex = -1;
  return out;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_INSERTION_BAD_TET_SHAPE_H
