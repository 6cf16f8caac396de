// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/mesh_pictures.h"

#include <CGAL/BODT_3/internal/Quality/dihedral_angles.h>
#include <CGAL/BODT_3/internal/Utilities/tet_face_matching.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace bodt_report {

namespace {

using CGAL::BODT_3::Tet_mesh;
using Vec = std::array<double, 3>;
using Point2 = std::array<double, 2>;

Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec plus(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec times(double s, const Vec& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec unit(const Vec& a) { return times(1 / length(a), a); }
Vec vec(const Tet_mesh::Point& p) { return {p.x(), p.y(), p.z()}; }

std::string format(const char* fmt, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// 12345 -> "12,345", for captions.
std::string count(std::size_t n)
{
  std::string digits = std::to_string(n), out;
  for(std::size_t i = 0; i < digits.size(); ++i)
  {
    if(i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string vector_text(const Vec& v)
{
  return "(" + format("%.3g", v[0]) + ", " + format("%.3g", v[1]) + ", " + format("%.3g", v[2]) + ")";
}

// The local vertices of the face of a tetrahedron opposite each vertex.
constexpr int opposite_faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

// A boundary face of a mesh.
struct Face
{
  std::array<int, 3> v;   // ordered so that (v1 - v0) x (v2 - v0) points out of the mesh
  std::size_t cell;       // position in Mesh_facts::cells
  long long patch;        // surface patch: a listed triangle's label, or else the subdomain it bounds
};

// What the pictures need to know about a mesh.
struct Mesh_facts
{
  std::vector<std::size_t> cells;           // the tetrahedra in the mesh
  std::vector<double> min_angle;            // of each, degrees
  std::vector<Face> outer;                  // the boundary faces
  std::vector<unsigned char> outline;       // per cell, bit i: its face opposite vertex i is on the
                                            // boundary or (for one of its two cells) an interface or
                                            // an embedded surface
  std::vector<std::size_t> worst;           // positions in `cells`, worst first
  std::vector<std::pair<int, int>> listed;  // the mesh's own feature edges, sorted (a < b)
};

// Boundary faces the file does not list get a patch of their own per subdomain.
constexpr long long unlisted_patch = 1LL << 40;

Mesh_facts facts_of(const Tet_mesh& m, int threads)
{
  Mesh_facts f;
  const bool all_zero = m.all_labels_zero();
  for(std::size_t t = 0; t < m.tets.size(); ++t)
    if(m.in_mesh(t, all_zero)) f.cells.push_back(t);
  std::vector<std::array<int, 4>> cells;
  cells.reserve(f.cells.size());
  for(std::size_t t : f.cells) cells.push_back(m.tets[t]);
  f.min_angle.resize(cells.size());
  for(std::size_t k = 0; k < cells.size(); ++k)
  {
    const auto& c = cells[k];
    f.min_angle[k] =
        CGAL::BODT_3::internal::min_max_dihedral_angle(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]).first;
  }
  f.worst.resize(cells.size());
  for(std::size_t k = 0; k < cells.size(); ++k) f.worst[k] = k;
  std::sort(f.worst.begin(), f.worst.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(f.min_angle[a], a) < std::tie(f.min_angle[b], b);
  });

  std::vector<std::pair<std::array<int, 3>, int>> listed_triangles;
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    std::array<int, 3> key = m.triangles[t];
    std::sort(key.begin(), key.end());
    listed_triangles.emplace_back(key, m.triangle_labels[t]);
  }
  std::sort(listed_triangles.begin(), listed_triangles.end());
  auto listed_label = [&](std::array<int, 3> key) -> const int* {
    std::sort(key.begin(), key.end());
    const auto it = std::lower_bound(listed_triangles.begin(), listed_triangles.end(),
                                     std::make_pair(key, std::numeric_limits<int>::min()));
    return it != listed_triangles.end() && it->first == key ? &it->second : nullptr;
  };

  const CGAL::BODT_3::internal::Tet_face_matching faces(cells, m.points.size(), threads);
  f.outline.assign(cells.size(), 0);
  for(std::size_t k = 0; k < cells.size(); ++k)
    for(int i = 0; i < 4; ++i)
    {
      const int match = faces.match[4 * k + static_cast<std::size_t>(i)];
      const int label = m.tet_labels[f.cells[k]];
      Face face;
      face.cell = k;
      for(int n = 0; n < 3; ++n) face.v[n] = cells[k][opposite_faces[i][n]];
      const int* listed = listed_label(face.v);
      if(match >= 0)
      {
        // Interfaces, and embedded surfaces (listed with a label other than 0), once each.
        const std::size_t other = static_cast<std::size_t>(match / 4);
        if((m.tet_labels[f.cells[other]] != label || (listed && *listed != 0)) && k < other)
          f.outline[k] |= static_cast<unsigned char>(1 << i);
        continue;
      }
      f.outline[k] |= static_cast<unsigned char>(1 << i);
      const Vec a = vec(m.points[face.v[0]]);
      const Vec normal = cross(minus(vec(m.points[face.v[1]]), a), minus(vec(m.points[face.v[2]]), a));
      if(dot(normal, minus(vec(m.points[cells[k][i]]), a)) > 0) std::swap(face.v[1], face.v[2]);
      face.patch = listed ? *listed : unlisted_patch + label;
      f.outer.push_back(face);
    }

  // The file's feature edges, as the smoothing reads them: without Ridges, edges
  // labelled 0 do not count when others are labelled (TetGen's -e lists them all).
  const bool some_labelled = std::any_of(m.edge_labels.begin(), m.edge_labels.end(), [](int l) { return l != 0; });
  for(std::size_t e = 0; e < m.edges.size(); ++e)
    if(!m.ridges.empty() || !some_labelled || m.edge_labels[e] != 0)
      f.listed.emplace_back(std::min(m.edges[e][0], m.edges[e][1]), std::max(m.edges[e][0], m.edges[e][1]));
  std::sort(f.listed.begin(), f.listed.end());
  return f;
}

// Whether the input carries feature information of its own, as the smoothing
// decides it: then its features are its edges and the lines where patches meet;
// otherwise tensor voting finds them, and the pictures draw the sharp edges.
bool has_feature_information(const Tet_mesh& m)
{
  if(!m.edges.empty() || !m.corners.empty() || !m.required_vertices.empty()) return true;
  for(int l : m.triangle_labels)
    if(l != m.triangle_labels.front()) return true;
  return false;
}

// An orthographic view: `toward` points at the viewer; pixels grow right and down.
struct Frame
{
  Vec right{}, up{}, toward{}, centre{};
  double scale = 1, cx = 0, cy = 0;

  Vec view(const Vec& p) const
  {
    const Vec d = minus(p, centre);
    return {cx + scale * dot(d, right), cy - scale * dot(d, up), scale * dot(d, toward)};
  }
};

Frame facing(const Vec& toward)
{
  Frame f;
  f.toward = unit(toward);
  // World z is up on the screen unless the view is along it.
  const Vec reference = std::abs(f.toward[2]) < 0.9 ? Vec{0, 0, 1} : Vec{0, 1, 0};
  f.right = unit(cross(reference, f.toward));
  f.up = cross(f.toward, f.right);
  return f;
}

// Scales and centres `f` so that `points` fill the picture but for a margin.
void fit(Frame& f, const std::vector<Vec>& points, int width, int height)
{
  f.cx = width / 2.0;
  f.cy = height / 2.0;
  if(points.empty()) return;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(const Vec& p : points)
  {
    const double s[2] = {dot(p, f.right), dot(p, f.up)};
    for(int k = 0; k < 2; ++k)
    {
      lo[k] = std::min(lo[k], s[k]);
      hi[k] = std::max(hi[k], s[k]);
    }
  }
  const double margin = 18, sx = hi[0] - lo[0], sy = hi[1] - lo[1], span = std::max(sx, sy);
  // A flat extent (a mesh seen edge-on) is fitted by the other one.
  f.scale = span > 0 ? std::min((width - 2 * margin) / std::max(sx, span * 1e-3),
                                (height - 2 * margin) / std::max(sy, span * 1e-3))
                     : 1.0;
  f.centre = plus(times((lo[0] + hi[0]) / 2, f.right), times((lo[1] + hi[1]) / 2, f.up));
}

// Light Lambert shading from the cosine between a face's normal and the view:
// enough to see the shape, not so much that the quality colours change name.
double shade_of(double cosine) { return 0.7 + 0.3 * cosine; }

struct Drawn_cell
{
  std::vector<Point2> points;
  double angle;    // smallest dihedral angle of the tetrahedron (the worst of those merged)
  double shade;    // 1: the colour as it is; less: darker (surfaces turned away)
  double depth;    // larger: nearer the viewer
  std::size_t order;
};

struct Drawn_segment
{
  Point2 a, b;
  double depth;
};

struct Marker
{
  Point2 at;
  double angle;
};

struct Picture
{
  std::vector<Drawn_cell> cells;          // in drawing order
  std::vector<Drawn_segment> features;    // by depth, drawn after the cells of the same depth
  std::vector<Marker> markers;            // worst first
  std::size_t source_cells = 0;           // cells to draw before simplification
  double merge_step = 0;                  // the grid step of the simplification, pixels; 0: none
};

// Vertices merged on a grid of step `step` (pixels): points in one grid cell become
// one, at their mean. `ids[i]` is the cluster of point i.
struct Clusters
{
  std::vector<int> ids;
  std::vector<Vec> at;
};

Clusters cluster(const std::vector<Vec>& points, double step, int dimensions)
{
  Clusters c;
  std::map<std::array<long long, 3>, int> cell_id;
  std::vector<double> weight;
  c.ids.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    std::array<long long, 3> key{{0, 0, 0}};
    for(int k = 0; k < dimensions; ++k) key[k] = static_cast<long long>(std::floor(points[i][k] / step));
    const auto inserted = cell_id.emplace(key, static_cast<int>(c.at.size()));
    if(inserted.second)
    {
      c.at.push_back({0, 0, 0});
      weight.push_back(0);
    }
    const int id = inserted.first->second;
    c.ids[i] = id;
    c.at[id] = plus(c.at[id], points[i]);
    weight[id] += 1;
  }
  for(std::size_t id = 0; id < c.at.size(); ++id) c.at[id] = times(1 / weight[id], c.at[id]);
  return c;
}

// The polygons (indices into `points`) drawn with merged vertices, with at most
// `max_cells` of them: merged polygons with the same vertices become one, keeping
// the worst angle, and a polygon that collapses gives its angle, if worse, to a
// polygon kept at one of its vertices, so that the worst cells still show.
// Returns the step used.
double simplify(std::vector<Drawn_cell>& cells, const std::vector<std::vector<std::size_t>>& corners,
                const std::vector<Vec>& points, int dimensions, std::size_t max_cells, double area,
                std::vector<Drawn_segment>& segments, const std::vector<std::array<std::size_t, 2>>& segment_ends)
{
  // A grid of step g over an area A holds about 2 A / g^2 triangles.
  double step = std::max(1e-3, std::sqrt(2 * area / static_cast<double>(max_cells)) * 0.8);
  const std::vector<Drawn_cell> original = cells;
  for(;; step *= 1.15)
  {
    const Clusters c = cluster(points, step, dimensions);
    std::map<std::vector<int>, std::size_t> merged;   // sorted cluster ids -> position in `cells`
    std::vector<std::pair<std::size_t, int>> collapsed;   // (original, one of its clusters)
    cells.clear();
    for(std::size_t k = 0; k < original.size(); ++k)
    {
      std::vector<int> ids;
      for(std::size_t p : corners[k])
        if(ids.empty() || c.ids[p] != ids.back()) ids.push_back(c.ids[p]);
      while(ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
      std::vector<int> key = ids;
      std::sort(key.begin(), key.end());
      if(key.size() < 3 || std::adjacent_find(key.begin(), key.end()) != key.end())
      {
        collapsed.emplace_back(k, ids.front());
        continue;
      }
      const auto found = merged.find(key);
      if(found != merged.end())
      {
        Drawn_cell& d = cells[found->second];
        if(original[k].angle < d.angle)
        {
          d.angle = original[k].angle;
          d.order = original[k].order;
        }
        continue;
      }
      Drawn_cell d = original[k];
      d.points.clear();
      Vec mean{0, 0, 0};
      for(int id : ids)
      {
        d.points.push_back({c.at[id][0], c.at[id][1]});
        mean = plus(mean, c.at[id]);
      }
      if(dimensions == 3)
      {
        d.depth = mean[2] / static_cast<double>(ids.size());
        const Vec n = cross(minus(c.at[ids[1]], c.at[ids[0]]), minus(c.at[ids[2]], c.at[ids[0]]));
        d.shade = length(n) > 0 ? shade_of(std::abs(n[2]) / length(n)) : 1.0;
      }
      merged.emplace(key, cells.size());
      cells.push_back(d);
    }
    if(cells.size() > max_cells) continue;
    std::map<int, std::size_t> kept_at;   // cluster -> the first kept polygon there
    for(const auto& [key, at] : merged)
      for(int id : key)
      {
        const auto it = kept_at.find(id);
        if(it == kept_at.end()) kept_at.emplace(id, at);
        else it->second = std::min(it->second, at);
      }
    for(const auto& [k, id] : collapsed)
    {
      const auto found = kept_at.find(id);
      if(found == kept_at.end() || !(original[k].angle < cells[found->second].angle)) continue;
      cells[found->second].angle = original[k].angle;
      cells[found->second].order = original[k].order;
    }
    std::map<std::pair<int, int>, std::size_t> kept;
    const std::vector<Drawn_segment> all = segments;
    segments.clear();
    for(std::size_t s = 0; s < all.size(); ++s)
    {
      int a = c.ids[segment_ends[s][0]], b = c.ids[segment_ends[s][1]];
      if(a == b) continue;
      const auto found = kept.find({std::min(a, b), std::max(a, b)});
      if(found != kept.end())
      {
        segments[found->second].depth = std::max(segments[found->second].depth, all[s].depth);
        continue;
      }
      kept.emplace(std::make_pair(std::min(a, b), std::max(a, b)), segments.size());
      segments.push_back({{c.at[a][0], c.at[a][1]}, {c.at[b][0], c.at[b][1]}, all[s].depth});
    }
    return step;
  }
}

// The boundary surface of `m` seen in `frame`: the faces turned towards the viewer,
// far to near, and the feature edges among them.
Picture surface_picture(const Tet_mesh& m, const Mesh_facts& f, const Frame& frame, bool listed_features,
                        const Picture_options& o)
{
  Picture p;
  // The boundary vertices in view coordinates, numbered compactly (`at`) so that
  // the simplification merges these only.
  std::vector<int> at(m.points.size(), -1);
  std::vector<Vec> view;
  for(const Face& face : f.outer)
    for(int v : face.v)
      if(at[v] < 0)
      {
        at[v] = static_cast<int>(view.size());
        view.push_back(frame.view(vec(m.points[v])));
      }

  std::vector<char> front(f.outer.size(), 0);
  std::vector<double> depth(f.outer.size(), 0);
  std::vector<std::vector<std::size_t>> corners;
  double area = 0;
  for(std::size_t k = 0; k < f.outer.size(); ++k)
  {
    const Face& face = f.outer[k];
    const Vec a = vec(m.points[face.v[0]]);
    const Vec n = cross(minus(vec(m.points[face.v[1]]), a), minus(vec(m.points[face.v[2]]), a));
    const double facing = dot(n, frame.toward);
    const Vec& a0 = view[at[face.v[0]]];
    const Vec& a1 = view[at[face.v[1]]];
    const Vec& a2 = view[at[face.v[2]]];
    depth[k] = (a0[2] + a1[2] + a2[2]) / 3;
    if(!(facing > 0)) continue;
    front[k] = 1;
    Drawn_cell d;
    for(const Vec* q : {&a0, &a1, &a2}) d.points.push_back({(*q)[0], (*q)[1]});
    d.angle = f.min_angle[face.cell];
    d.shade = shade_of(facing / length(n));
    d.depth = depth[k];
    d.order = f.cells[face.cell];
    p.cells.push_back(d);
    corners.push_back({static_cast<std::size_t>(at[face.v[0]]), static_cast<std::size_t>(at[face.v[1]]),
                       static_cast<std::size_t>(at[face.v[2]])});
    const Vec e1 = minus(a1, a0), e2 = minus(a2, a0);
    area += std::abs(e1[0] * e2[1] - e1[1] * e2[0]) / 2;
  }
  p.source_cells = p.cells.size();

  // Feature edges: the edges of the boundary faces, each with the faces on it.
  std::vector<std::tuple<int, int, std::size_t>> edges;
  for(std::size_t k = 0; k < f.outer.size(); ++k)
    for(int i = 0; i < 3; ++i)
    {
      const int a = f.outer[k].v[i], b = f.outer[k].v[(i + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b), k);
    }
  std::sort(edges.begin(), edges.end());
  const double cos_feature = std::cos(o.feature_angle * bodt_cli::pi / 180);
  std::vector<std::array<std::size_t, 2>> segment_ends;
  for(std::size_t begin = 0, end; begin < edges.size(); begin = end)
  {
    const int a = std::get<0>(edges[begin]), b = std::get<1>(edges[begin]);
    end = begin;
    double nearest = -std::numeric_limits<double>::infinity();
    while(end < edges.size() && std::get<0>(edges[end]) == a && std::get<1>(edges[end]) == b)
    {
      const std::size_t k = std::get<2>(edges[end]);
      if(front[k]) nearest = std::max(nearest, depth[k]);
      ++end;
    }
    if(nearest == -std::numeric_limits<double>::infinity()) continue;   // hidden: no face on it is drawn
    bool feature = end - begin != 2;
    if(!feature)
    {
      const Face& s = f.outer[std::get<2>(edges[begin])];
      const Face& t = f.outer[std::get<2>(edges[begin + 1])];
      feature = s.patch != t.patch;
      if(!feature && listed_features)
        feature = std::binary_search(f.listed.begin(), f.listed.end(), std::make_pair(a, b));
      else if(!feature)
      {
        auto normal = [&](const Face& g) {
          const Vec q = vec(m.points[g.v[0]]);
          return cross(minus(vec(m.points[g.v[1]]), q), minus(vec(m.points[g.v[2]]), q));
        };
        const Vec ns = normal(s), nt = normal(t);
        feature = dot(ns, nt) < cos_feature * length(ns) * length(nt);
      }
    }
    if(!feature) continue;
    const Vec& va = view[at[a]];
    const Vec& vb = view[at[b]];
    p.features.push_back({{va[0], va[1]}, {vb[0], vb[1]}, nearest});
    segment_ends.push_back({static_cast<std::size_t>(at[a]), static_cast<std::size_t>(at[b])});
  }

  if(p.cells.size() > o.max_cells)
    p.merge_step = simplify(p.cells, corners, view, 3, o.max_cells, area, p.features, segment_ends);
  std::stable_sort(p.cells.begin(), p.cells.end(), [](const Drawn_cell& x, const Drawn_cell& y) {
    return std::tie(x.depth, x.order) < std::tie(y.depth, y.order);
  });
  std::stable_sort(p.features.begin(), p.features.end(),
                   [](const Drawn_segment& x, const Drawn_segment& y) { return x.depth < y.depth; });

  for(std::size_t r = 0; r < std::min(o.marked_worst, f.worst.size()); ++r)
  {
    const auto& c = m.tets[f.cells[f.worst[r]]];
    Vec centroid{0, 0, 0};
    for(int v : c) centroid = plus(centroid, vec(m.points[v]));
    const Vec at = frame.view(times(0.25, centroid));
    p.markers.push_back({{at[0], at[1]}, f.min_angle[f.worst[r]]});
  }
  return p;
}

// The cut of `m` by `plane`, seen from the side its normal points to: one polygon
// per tetrahedron cut, and the lines where the plane crosses the boundary and the
// interfaces.
Picture cut_picture(const Tet_mesh& m, const Mesh_facts& f, const Cut_plane& plane, const Frame& frame,
                    const Picture_options& o)
{
  Picture p;
  const Vec normal = unit({plane.normal[0], plane.normal[1], plane.normal[2]});
  const Vec origin = {plane.point[0], plane.point[1], plane.point[2]};
  auto side = [&](int v) { return dot(minus(vec(m.points[v]), origin), normal); };
  // Where the plane crosses edge (a, b), a below it and b not: b itself when it
  // lies on the plane, otherwise a point computed from the edge's lower-numbered
  // vertex. Either way every cell around the edge gets the same point, bit for
  // bit, under one number.
  std::vector<Vec> points;
  std::map<std::pair<int, int>, std::size_t> crossing;
  auto cross_at = [&](int a, int b) {
    const double db = side(b);
    const std::pair<int, int> key = db == 0 ? std::make_pair(b, b) : std::make_pair(std::min(a, b), std::max(a, b));
    const auto found = crossing.find(key);
    if(found != crossing.end()) return found->second;
    const int u = key.first, w = key.second;
    const double du = side(u), dw = side(w);
    const Vec pu = vec(m.points[u]), pw = vec(m.points[w]);
    const Vec at = frame.view(u == w ? pu : plus(pu, times(du / (du - dw), minus(pw, pu))));
    crossing.emplace(key, points.size());
    points.push_back({at[0], at[1], 0});
    return points.size() - 1;
  };
  // The crossing points of the edges among `vertices` (local indices of `c`) that
  // go from below the plane to not below it, each once.
  auto crossings = [&](const std::array<int, 4>& c, const bool* below, std::initializer_list<int> vertices) {
    std::vector<std::size_t> ids;
    for(int a : vertices)
      for(int b : vertices)
        if(below[a] && !below[b]) ids.push_back(cross_at(c[a], c[b]));
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  };
  std::vector<std::vector<std::size_t>> corners;
  std::vector<std::array<std::size_t, 2>> segment_ends;
  double area = 0;
  for(std::size_t k = 0; k < f.cells.size(); ++k)
  {
    const auto& c = m.tets[f.cells[k]];
    bool below[4];
    int count_below = 0, count_above = 0;
    for(int i = 0; i < 4; ++i)
    {
      const double d = side(c[i]);
      below[i] = d < 0;
      count_below += d < 0;
      count_above += d > 0;
    }
    // A cell is cut where the plane crosses its inside, and a face lying in the
    // plane is drawn once, as the cut of the cell below it; a cell that touches
    // the plane at a vertex or an edge only is not.
    const bool crossed = count_below > 0 && count_above > 0;
    const bool face_on_plane = count_below == 1 && count_above == 0;
    if(!crossed && !face_on_plane) continue;
    std::vector<std::size_t> ring = crossings(c, below, {0, 1, 2, 3});
    // The crossing points of a convex cell, in order around their mean.
    double mx = 0, my = 0;
    for(std::size_t q : ring) mx += points[q][0], my += points[q][1];
    mx /= static_cast<double>(ring.size());
    my /= static_cast<double>(ring.size());
    std::sort(ring.begin(), ring.end(), [&](std::size_t a, std::size_t b) {
      return std::atan2(points[a][1] - my, points[a][0] - mx) < std::atan2(points[b][1] - my, points[b][0] - mx);
    });
    Drawn_cell d;
    for(std::size_t q : ring) d.points.push_back({points[q][0], points[q][1]});
    for(std::size_t q = 0; q < ring.size(); ++q)
    {
      const auto& u = points[ring[q]];
      const auto& w = points[ring[(q + 1) % ring.size()]];
      area += (u[0] * w[1] - w[0] * u[1]) / 2;
    }
    d.angle = f.min_angle[k];
    d.shade = 1;
    d.depth = 0;
    d.order = f.cells[k];
    p.cells.push_back(d);
    corners.push_back(ring);
    for(int i = 0; i < 4; ++i)
    {
      if(!(f.outline[k] >> i & 1)) continue;
      const auto& o3 = opposite_faces[i];
      const std::vector<std::size_t> ends = crossings(c, below, {o3[0], o3[1], o3[2]});
      if(ends.size() != 2) continue;
      p.features.push_back({{points[ends[0]][0], points[ends[0]][1]}, {points[ends[1]][0], points[ends[1]][1]},
                            std::numeric_limits<double>::infinity()});
      segment_ends.push_back({ends[0], ends[1]});
    }
  }
  p.source_cells = p.cells.size();

  // The worst cells cut, ringed at the middle of their polygon.
  std::vector<std::size_t> by_quality(p.cells.size());
  for(std::size_t k = 0; k < by_quality.size(); ++k) by_quality[k] = k;
  std::sort(by_quality.begin(), by_quality.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(p.cells[a].angle, p.cells[a].order) < std::tie(p.cells[b].angle, p.cells[b].order);
  });
  for(std::size_t r = 0; r < std::min(o.marked_worst, by_quality.size()); ++r)
  {
    const Drawn_cell& d = p.cells[by_quality[r]];
    Point2 mean{0, 0};
    for(const Point2& q : d.points) mean[0] += q[0], mean[1] += q[1];
    p.markers.push_back({{mean[0] / d.points.size(), mean[1] / d.points.size()}, d.angle});
  }

  if(p.cells.size() > o.max_cells)
    p.merge_step = simplify(p.cells, corners, points, 2, o.max_cells, std::abs(area), p.features, segment_ends);
  // The worst drawn last, on top of what merged vertices may make overlap.
  std::stable_sort(p.cells.begin(), p.cells.end(), [](const Drawn_cell& x, const Drawn_cell& y) {
    return std::tie(y.angle, x.order) < std::tie(x.angle, y.order);
  });
  return p;
}

// SVG path data in tenths of a pixel, as integers: vertices shared by two cells
// meet exactly, and relative steps stay short.
void put_number(std::string& out, long long tenths)
{
  if(tenths < 0)
  {
    out += '-';
    tenths = -tenths;
  }
  const long long whole = tenths / 10, fraction = tenths % 10;
  if(whole > 0 || fraction == 0) out += std::to_string(whole);
  if(fraction > 0)
  {
    out += '.';
    out += static_cast<char>('0' + fraction);
  }
}

void put_pair(std::string& out, long long x, long long y)
{
  put_number(out, x);
  if(y >= 0) out += ' ';
  put_number(out, y);
}

void put_path(std::string& out, const std::vector<Point2>& points, bool close)
{
  long long px = 0, py = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const long long x = std::llround(points[i][0] * 10), y = std::llround(points[i][1] * 10);
    out += i == 0 ? 'M' : 'l';
    if(i == 0)
      put_pair(out, x, y);
    else
      put_pair(out, x - px, y - py);
    px = x;
    py = y;
  }
  if(close) out += 'z';
}

std::array<double, 3> quality_rgb(double degrees)
{
  // ColorBrewer's RdYlGn, from 0 degrees to the regular tetrahedron's 70.53.
  static const double stops[][4] = {{0, 165, 0, 38},       {10, 215, 48, 39},     {20, 244, 109, 67},
                                    {30, 253, 174, 97},    {40, 254, 224, 139},   {50, 217, 239, 139},
                                    {60, 166, 217, 106},   {70.53, 26, 152, 80}};
  const std::size_t n = sizeof stops / sizeof stops[0];
  if(!(degrees > stops[0][0])) return {stops[0][1], stops[0][2], stops[0][3]};
  for(std::size_t k = 1; k < n; ++k)
    if(degrees < stops[k][0])
    {
      const double t = (degrees - stops[k - 1][0]) / (stops[k][0] - stops[k - 1][0]);
      return {stops[k - 1][1] + t * (stops[k][1] - stops[k - 1][1]), stops[k - 1][2] + t * (stops[k][2] - stops[k - 1][2]),
              stops[k - 1][3] + t * (stops[k][3] - stops[k - 1][3])};
    }
  return {stops[n - 1][1], stops[n - 1][2], stops[n - 1][3]};
}

std::string hex_colour(const std::array<double, 3>& rgb, double shade)
{
  char buf[8];
  auto byte = [&](double x) { return static_cast<int>(std::lround(std::min(255.0, std::max(0.0, x * shade)))); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(rgb[0]), byte(rgb[1]), byte(rgb[2]));
  return buf;
}

struct Picture_labels
{
  const char* kind;    // "surface" or "cut"
  const char* stage;   // "before" or "after"
  const char* background;
  std::string data;    // more data attributes
  std::string empty;   // what the picture says when it has no cell
};

std::string picture_svg(const Picture& p, const Picture_labels& l, const Picture_options& o)
{
  std::string s;
  s += "<svg class=\"mesh-picture" + std::string(p.merge_step > 0 ? " dense" : "") + "\" data-kind=\"" + l.kind +
       "\" data-stage=\"" + l.stage + "\" data-cells=\"" + std::to_string(p.cells.size()) +
       "\" data-source-cells=\"" + std::to_string(p.source_cells) + "\" data-features=\"" +
       std::to_string(p.features.size()) + "\" data-marked=\"" + std::to_string(p.markers.size()) + "\"" + l.data +
       " width=\"" + std::to_string(o.width) + "\" height=\"" + std::to_string(o.height) + "\" viewBox=\"0 0 " +
       std::to_string(o.width) + " " + std::to_string(o.height) + "\" role=\"img\" aria-label=\"" + l.kind + " " +
       l.stage + "\">\n";
  s += "<rect width=\"" + std::to_string(o.width) + "\" height=\"" + std::to_string(o.height) + "\" fill=\"" +
       l.background + "\"/>\n";
  if(p.cells.empty())
    s += "<text x=\"" + std::to_string(o.width / 2) + "\" y=\"" + std::to_string(o.height / 2) +
         "\" text-anchor=\"middle\">" + l.empty + "</text>\n";
  s += "<g class=\"cells\">\n";
  // Faces and feature edges far to near: an edge goes after the faces as near as
  // it is, so that nearer faces hide it. The cut's lines are at infinity: on top.
  std::size_t e = 0;
  auto put_features = [&](bool all, double nearer_than) {
    std::string d;
    for(; e < p.features.size() && (all || p.features[e].depth < nearer_than); ++e)
      put_path(d, {p.features[e].a, p.features[e].b}, false);
    if(!d.empty()) s += "<path class=\"fe\" d=\"" + d + "\"/>\n";
  };
  for(const Drawn_cell& c : p.cells)
  {
    put_features(false, c.depth);
    s += "<path d=\"";
    put_path(s, c.points, true);
    s += "\" fill=\"" + hex_colour(quality_rgb(c.angle), c.shade) + "\"/>\n";
  }
  put_features(true, 0);
  s += "</g>\n<g class=\"worst\">\n";
  for(std::size_t r = 0; r < p.markers.size(); ++r)
  {
    const std::string cx = format("%.1f", p.markers[r].at[0]), cy = format("%.1f", p.markers[r].at[1]);
    s += "<circle class=\"halo\" cx=\"" + cx + "\" cy=\"" + cy + "\" r=\"8\"/><circle cx=\"" + cx + "\" cy=\"" + cy +
         "\" r=\"8\"/><text x=\"" + format("%.1f", p.markers[r].at[0] + 9) + "\" y=\"" +
         format("%.1f", p.markers[r].at[1] - 9) + "\">" + std::to_string(r + 1) + "</text>\n";
  }
  s += "</g>\n</svg>\n";
  return s;
}

std::string legend_svg()
{
  const int width = 600, height = 58, left = 10, bar = 360;
  std::string s = "<svg class=\"legend\" width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) +
                  "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
                  "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  const double top_angle = 72;
  for(double a = 0; a < top_angle; a += 2)
    s += "<rect x=\"" + format("%.1f", left + bar * a / top_angle) + "\" y=\"8\" width=\"" +
         format("%.1f", bar * 2 / top_angle + 0.5) + "\" height=\"16\" fill=\"" +
         hex_colour(quality_rgb(a + 1), 1) + "\"/>\n";
  for(int a = 0; a <= 70; a += 10)
    s += "<text x=\"" + format("%.1f", left + bar * a / top_angle) + "\" y=\"40\" text-anchor=\"middle\">" +
         std::to_string(a) + "&#176;</text>\n";
  s += "<text x=\"" + std::to_string(left) + "\" y=\"54\">smallest dihedral angle of the tetrahedron</text>\n";
  s += "<circle cx=\"400\" cy=\"16\" r=\"7\" fill=\"none\" stroke=\"" + std::string(worst_ring_colour) +
       "\" stroke-width=\"2.5\"/><text x=\"414\" y=\"20\">worst tetrahedra (1: the worst)</text>\n";
  s += "<line x1=\"393\" y1=\"40\" x2=\"407\" y2=\"40\" stroke=\"" + std::string(feature_edge_colour) +
       "\" stroke-width=\"1.5\"/><text x=\"414\" y=\"44\">feature edges, boundary in the cut</text>\n";
  return s + "</svg>\n";
}

std::string worst_text(const Picture& p, const char* which)
{
  if(p.markers.empty()) return "";
  return " Ringed: the " + count(p.markers.size()) + " worst tetrahedra" + which + " (1: " +
         format("%.2f", p.markers[0].angle) + "&deg;).";
}

std::string simplified_text(const Picture& p, const char* what)
{
  if(p.merge_step <= 0) return "";
  return " <b>Simplified</b> to keep the page small: the " + count(p.source_cells) + " " + what +
         " are drawn as " + count(p.cells.size()) + ", by merging vertices less than " +
         format("%.1f", p.merge_step) + " px apart; each keeps the worst angle of those it stands for.";
}

std::string plane_data(const Cut_plane& c)
{
  std::string s = " data-plane=\"";
  for(int k = 0; k < 3; ++k) s += format("%.17g", c.point[k]) + " ";
  for(int k = 0; k < 3; ++k) s += format("%.17g", c.normal[k]) + (k < 2 ? " " : "\"");
  return s;
}

} // namespace

Cut_plane parse_cut_plane(const std::string& text)
{
  const std::string usage = "'" + text + "' is not a plane: give x=V, y=V, z=V or PX,PY,PZ,NX,NY,NZ";
  auto number = [&](std::string t) {
    while(!t.empty() && t.front() == ' ') t.erase(t.begin());
    while(!t.empty() && t.back() == ' ') t.pop_back();
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if(t.empty() || end != t.c_str() + t.size()) throw std::invalid_argument(usage);
    if(!std::isfinite(x)) throw std::invalid_argument("'" + text + "': the numbers must be finite");
    return x;
  };
  Cut_plane c;
  const std::size_t equals = text.find('=');
  if(equals != std::string::npos)
  {
    std::string axis = text.substr(0, equals);
    axis.erase(std::remove(axis.begin(), axis.end(), ' '), axis.end());
    if(axis.size() != 1 || std::string("xyzXYZ").find(axis[0]) == std::string::npos)
      throw std::invalid_argument(usage);
    const int k = (axis[0] | 0x20) - 'x';
    c.point = {0, 0, 0};
    c.normal = {0, 0, 0};
    c.point[k] = number(text.substr(equals + 1));
    c.normal[k] = 1;
    return c;
  }
  std::vector<double> v;
  for(std::size_t begin = 0;;)
  {
    const std::size_t comma = text.find(',', begin);
    v.push_back(number(text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin)));
    if(comma == std::string::npos) break;
    begin = comma + 1;
  }
  if(v.size() != 6) throw std::invalid_argument(usage);
  c.point = {v[0], v[1], v[2]};
  c.normal = {v[3], v[4], v[5]};
  if(!(length(c.normal) > 0)) throw std::invalid_argument("'" + text + "': the normal (NX,NY,NZ) must not be zero");
  return c;
}

bool plane_meets_mesh(const Cut_plane& plane, const Tet_mesh& mesh)
{
  const bool all_zero = mesh.all_labels_zero();
  Vec lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::infinity()};
  Vec hi = times(-1, lo);
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    if(mesh.in_mesh(t, all_zero))
      for(int v : mesh.tets[t])
        for(int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], mesh.points[v][k]);
          hi[k] = std::max(hi[k], mesh.points[v][k]);
        }
  if(lo[0] > hi[0]) return false;
  double below = std::numeric_limits<double>::infinity(), above = -below;
  for(int corner = 0; corner < 8; ++corner)
  {
    const Vec p{corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1], corner & 4 ? hi[2] : lo[2]};
    const double d = dot(minus(p, {plane.point[0], plane.point[1], plane.point[2]}), plane.normal);
    below = std::min(below, d);
    above = std::max(above, d);
  }
  return below <= 0 && above >= 0;
}

std::string quality_colour(double degrees) { return hex_colour(quality_rgb(degrees), 1); }

std::array<double, 3> surface_view_direction() { return unit({0.6, -1.0, 0.75}); }

std::string mesh_pictures_html(const Tet_mesh& before, const Tet_mesh& after, const Picture_options& o)
{
  const Mesh_facts fb = facts_of(before, o.threads), fa = facts_of(after, o.threads);
  const bool listed = has_feature_information(before);

  Frame surface = facing(surface_view_direction());
  {
    std::vector<Vec> boundary;
    for(const Face& face : fb.outer)
      for(int v : face.v) boundary.push_back(vec(before.points[v]));
    fit(surface, boundary, o.width, o.height);
  }

  Cut_plane plane;
  std::string plane_text;
  if(o.cut)
  {
    plane = *o.cut;
    plane_text = "the plane through " + vector_text(plane.point) + " with normal " + vector_text(plane.normal) +
                 " (given by --cut)";
  }
  else
  {
    plane.normal = surface_view_direction();
    if(!fb.worst.empty())
    {
      Vec centroid{0, 0, 0};
      for(int v : before.tets[fb.cells[fb.worst[0]]]) centroid = plus(centroid, vec(before.points[v]));
      centroid = times(0.25, centroid);
      plane.point = centroid;
    }
    plane_text = "the plane through the centroid of the input's worst tetrahedron, " + vector_text(plane.point) +
                 ", facing the viewer of the surface pictures";
  }
  Frame cut = facing({plane.normal[0], plane.normal[1], plane.normal[2]});
  {
    // Fitted to the input's cut, or to the whole input when the plane misses it.
    Frame unit_frame = cut;
    unit_frame.scale = 1;
    Picture_options everything = o;
    everything.max_cells = std::numeric_limits<std::size_t>::max();
    const Picture probe = cut_picture(before, fb, plane, unit_frame, everything);
    std::vector<Vec> fitted;
    for(const Drawn_cell& d : probe.cells)
      for(const Point2& q : d.points)
        fitted.push_back(plus(plus(times(q[0], cut.right), times(-q[1], cut.up)), unit_frame.centre));
    if(fitted.empty())
      for(const Face& face : fb.outer)
        for(int v : face.v) fitted.push_back(vec(before.points[v]));
    fit(cut, fitted, o.width, o.height);
  }

  const Picture surface_before = surface_picture(before, fb, surface, listed, o);
  const Picture surface_after = surface_picture(after, fa, surface, listed, o);
  const Picture cut_before = cut_picture(before, fb, plane, cut, o);
  const Picture cut_after = cut_picture(after, fa, plane, cut, o);

  const Vec toward = surface.toward;
  const std::string view_data = " data-view=\"" + format("%.17g", toward[0]) + " " + format("%.17g", toward[1]) +
                                " " + format("%.17g", toward[2]) + "\"";
  const std::string features =
      listed ? "the input's own feature edges and the lines where its surface patches meet"
             : "the edges where the surface turns by more than " + format("%.4g", o.feature_angle) +
                   "&deg; (the feature angle) and where subdomains meet";

  std::string h = "<h2>The mesh</h2>\n<p class=\"what\">The boundary surface seen from " + vector_text(toward) +
                  " and a cut through the mesh, before (grey) and after (blue) in the same frame. Each triangle of "
                  "the surface has the colour of its tetrahedron, each polygon of the cut the colour of the "
                  "tetrahedron it cuts, by the smallest dihedral angle of that tetrahedron (legend below). Black "
                  "lines: " + features + " on the surface; the boundary and the interfaces in the cut.</p>\n";
  h += "<div class=\"pictures\">\n";
  auto figure = [&](const Picture& p, const Picture_labels& l, const std::string& caption) {
    h += "<figure>\n" + picture_svg(p, l, o) + "<figcaption>" + caption + "</figcaption>\n</figure>\n";
  };
  auto surface_caption = [&](const char* stage, const Picture& p, const Mesh_facts& f) {
    return std::string(stage) + ": " + count(p.source_cells) + " of the " + count(f.outer.size()) +
           " boundary triangles face the viewer; " + count(p.features.size()) + " feature edges drawn." +
           worst_text(p, ", even where the surface hides them") + simplified_text(p, "triangles");
  };
  auto cut_caption = [&](const char* stage, const Picture& p) {
    return std::string(stage) + ": " + plane_text + " cuts " + count(p.source_cells) + " tetrahedra." +
           worst_text(p, " it cuts") + simplified_text(p, "polygons");
  };
  figure(surface_before, {"surface", "before", picture_before_background, view_data, ""},
         surface_caption("Before", surface_before, fb));
  figure(surface_after, {"surface", "after", picture_after_background, view_data, ""},
         surface_caption("After", surface_after, fa));
  figure(cut_before, {"cut", "before", picture_before_background, plane_data(plane), "the plane cuts no tetrahedron"},
         cut_caption("Before", cut_before));
  figure(cut_after, {"cut", "after", picture_after_background, plane_data(plane), "the plane cuts no tetrahedron"},
         cut_caption("After", cut_after));
  h += "</div>\n<figure class=\"legend\">\n" + legend_svg() + "</figure>\n";
  return h;
}

} // namespace bodt_report
