// Boxes and L-shaped blocks of tetrahedra, labelled the ways users of Gmsh, Medit,
// TetGen and libigl label them, with what the smoothing must keep of their shape:
// the planes of their faces, interfaces and embedded surfaces, hence their straight
// edges and their corners.
#ifndef BODT_TEST_LABELLED_BOXES_H
#define BODT_TEST_LABELLED_BOXES_H

#include <CGAL/BODT_3/Tet_mesh.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace bodt_test {

enum class Outline { box, l_shape };                          // the outer boundary
enum class Parts { one, two_halves, inclusion };              // the subdomains
// The triangles' labels; with `none`, only an embedded surface's triangles are listed (ref 7).
enum class Refs { none, one_for_all, one_per_face, one_per_subdomain_pair };
enum class Embedded { none, through, inside, from_boundary }; // an embedded surface on the mid plane

struct Labelled_box_case
{
  Outline outline = Outline::box;
  Parts parts = Parts::one;
  Refs refs = Refs::none;
  Embedded embedded = Embedded::none;
  bool rotated = false;   // rotated, scaled and moved, so that no plane is a coordinate plane
  int n = 6;              // cubes along each side (even; 6 or more with an inclusion)

  std::string name() const
  {
    static const char* outlines[] = {"box", "L"};
    static const char* partss[] = {"one_subdomain", "two_halves", "inclusion"};
    static const char* refss[] = {"no_triangles", "one_ref", "ref_per_face", "ref_per_subdomain_pair"};
    static const char* embeddeds[] = {"", "_sheet_through", "_sheet_inside", "_sheet_from_boundary"};
    return std::string(outlines[int(outline)]) + "_" + partss[int(parts)] + "_" + refss[int(refs)] +
           embeddeds[int(embedded)] + (rotated ? "_rotated" : "");
  }
};

/// Every labelling a user can give, on both outlines: no triangles, one ref for all,
/// one per face, one per subdomain pair; one subdomain with or without an embedded
/// surface (cutting through, ending inside, or meeting the boundary and ending
/// inside), two subdomains, an inclusion; axis-aligned and rotated.
inline std::vector<Labelled_box_case> all_labelled_box_cases()
{
  std::vector<Labelled_box_case> cases;
  for(bool rotated : {false, true})
    for(Outline o : {Outline::box, Outline::l_shape})
      for(Parts p : {Parts::one, Parts::two_halves, Parts::inclusion})
        for(Refs r : {Refs::none, Refs::one_for_all, Refs::one_per_face, Refs::one_per_subdomain_pair})
          for(Embedded e : {Embedded::none, Embedded::through, Embedded::inside, Embedded::from_boundary})
            if(p == Parts::one || e == Embedded::none) cases.push_back({o, p, r, e, rotated});
  return cases;
}

/// A plane of the input: points x with normal * x = offset.
struct Kept_plane
{
  CGAL::BODT_3::Tet_mesh::Kernel::Vector_3 normal;   // unit
  double offset;
};

struct Labelled_box
{
  CGAL::BODT_3::Tet_mesh mesh;
  std::vector<Kept_plane> planes;        // faces of the outline, interfaces, the embedded surface
  std::vector<std::vector<int>> on;      // per vertex: the planes it lies on
  double size = 1;                       // the length of the box's side
};

/// The case's mesh: an n x n x n grid of cubes, each cut into six
/// tetrahedra; the L-shape leaves out the cubes with i, j >= n / 2. The inclusion is
/// the cubes in [2, 4)^3, subdomain 2 inside subdomain 1 (in the L-shape it reaches
/// the outline's inner edge, where its interface meets the boundary); the halves split at
/// k = n / 2, as does the embedded surface (triangles between tetrahedra of one
/// label): all of the plane, the part with i and j in [1, n - 1], or the part with
/// i <= n / 2 (on the boundary at x = 0, y = 0 and y = n, ending inside). Every
/// vertex is moved by a seeded random amount of up to 0.2 of a cube along the axes
/// whose planes it does not lie on.
inline Labelled_box make_labelled_box(const Labelled_box_case& c)
{
  using Point = CGAL::BODT_3::Tet_mesh::Point;
  using Vector = CGAL::BODT_3::Tet_mesh::Kernel::Vector_3;
  const int n = c.n, mid = n / 2;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  auto removed = [&](int i, int j) { return c.outline == Outline::l_shape && i >= mid && j >= mid; };
  auto label = [&](int i, int j, int k) {
    if(c.parts == Parts::two_halves) return k < mid ? 1 : 2;
    if(c.parts == Parts::inclusion) return (i >= 2 && i < 4 && j >= 2 && j < 4 && k >= 2 && k < 4) ? 2 : 1;
    return 1;
  };

  // Tetrahedra on grid points, then the faces between different labels (or a
  // label and the outside), each with the plane (axis, grid value) it lies on.
  Labelled_box out;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> labels;
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        if(removed(i, j)) continue;
        std::array<int, 3> axes{0, 1, 2};
        do
        {
          std::array<int, 3> g{i, j, k};
          std::array<int, 4> t{};
          t[0] = id(g[0], g[1], g[2]);
          for(int s = 0; s < 3; ++s)
          {
            ++g[axes[s]];
            t[s + 1] = id(g[0], g[1], g[2]);
          }
          tets.push_back(t);
          labels.push_back(label(i, j, k));
        } while(std::next_permutation(axes.begin(), axes.end()));
      }
  auto grid = [n](int v) { return std::array<int, 3>{v % (n + 1), v / (n + 1) % (n + 1), v / ((n + 1) * (n + 1))}; };
  // A face's plane: the axis on which its three grid points agree.
  auto plane_of = [&](const std::array<int, 3>& f) {
    for(int a = 0; a < 3; ++a)
      if(grid(f[0])[a] == grid(f[1])[a] && grid(f[1])[a] == grid(f[2])[a]) return std::make_pair(a, grid(f[0])[a]);
    return std::make_pair(-1, 0);
  };
  std::map<std::array<int, 3>, std::vector<int>> face_tets;   // sorted face -> tetrahedra
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int i = 0; i < 4; ++i)
    {
      std::array<int, 3> f = {tets[t][(i + 1) % 4], tets[t][(i + 2) % 4], tets[t][(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      face_tets[f].push_back(static_cast<int>(t));
    }
  auto embedded = [&](const std::array<int, 3>& f) {
    if(c.embedded == Embedded::none || plane_of(f) != std::make_pair(2, mid)) return false;
    for(int v : f)
    {
      const auto g = grid(v);
      if(c.embedded == Embedded::inside && (g[0] < 1 || g[0] > n - 1 || g[1] < 1 || g[1] > n - 1)) return false;
      if(c.embedded == Embedded::from_boundary && g[0] > mid) return false;
    }
    return true;
  };
  struct Listed { std::array<int, 3> face; int side0, side1; };   // sides: labels, 0 outside
  std::vector<Listed> surface;
  for(const auto& [f, ts] : face_tets)
  {
    const int s0 = labels[ts[0]], s1 = ts.size() > 1 ? labels[ts[1]] : 0;
    if(s0 != s1 || embedded(f)) surface.push_back({f, std::min(s0, s1), std::max(s0, s1)});
  }

  // The planes, and the axes each vertex may not move along.
  std::map<std::pair<int, int>, int> plane_index;
  std::vector<std::pair<int, int>> grid_planes;
  const int nv = (n + 1) * (n + 1) * (n + 1);
  out.on.assign(nv, {});
  std::vector<std::array<bool, 3>> held(nv, {false, false, false});
  for(const Listed& l : surface)
  {
    const auto p = plane_of(l.face);
    const auto it = plane_index.emplace(p, static_cast<int>(grid_planes.size())).first;
    if(it->second == static_cast<int>(grid_planes.size())) grid_planes.push_back(p);
    for(int v : l.face)
    {
      held[v][p.first] = true;
      if(std::find(out.on[v].begin(), out.on[v].end(), it->second) == out.on[v].end()) out.on[v].push_back(it->second);
    }
  }

  // Positions: the grid, jittered, then (rotated) turned about (1, 2, 3) by 0.7
  // radians, scaled by 3.7 and moved, which makes every coordinate inexact.
  CGAL::Random random(11);
  const double h = 1.0 / n;
  const double scale = c.rotated ? 3.7 : 1.0;
  const Vector axis = Vector(1, 2, 3) / std::sqrt(14.0), shift = c.rotated ? Vector(10, -5, 2) : Vector(0, 0, 0);
  const double angle = c.rotated ? 0.7 : 0.0, cs = std::cos(angle), sn = std::sin(angle);
  auto place = [&](const Vector& x) {   // Rodrigues' rotation, then scale and shift
    const Vector r = x * cs + CGAL::cross_product(axis, x) * sn + axis * ((axis * x) * (1 - cs));
    return r * scale + shift;
  };
  std::vector<Point> points(nv);
  for(int v = 0; v < nv; ++v)
  {
    const auto g = grid(v);
    double x[3];
    for(int a = 0; a < 3; ++a)
    {
      const double jitter = random.get_double(-0.2, 0.2);
      x[a] = (g[a] + (held[v][a] ? 0.0 : jitter)) * h;
    }
    points[v] = CGAL::ORIGIN + place(Vector(x[0], x[1], x[2]));
  }
  for(const auto& p : grid_planes)
  {
    Vector normal(p.first == 0, p.first == 1, p.first == 2);
    const Vector on_plane = normal * (p.second * h);
    normal = place(normal) - place(Vector(0, 0, 0));
    normal = normal / std::sqrt(normal.squared_length());
    out.planes.push_back({normal, normal * place(on_plane)});
  }
  out.size = scale;

  // The mesh: the used points, renumbered; tetrahedra positively oriented.
  std::vector<int> number(nv, -1);
  auto& m = out.mesh;
  std::vector<std::vector<int>> on;
  for(const auto& t : tets)
    for(int v : t)
      if(number[v] < 0)
      {
        number[v] = static_cast<int>(m.points.size());
        m.points.push_back(points[v]);
        on.push_back(out.on[v]);
      }
  out.on.swap(on);
  m.vertex_refs.assign(m.points.size(), 0);
  for(std::size_t t = 0; t < tets.size(); ++t)
  {
    std::array<int, 4> q = {number[tets[t][0]], number[tets[t][1]], number[tets[t][2]], number[tets[t][3]]};
    if(CGAL::orientation(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]) != CGAL::POSITIVE)
      std::swap(q[2], q[3]);
    m.tets.push_back(q);
    m.tet_labels.push_back(labels[t]);
  }
  for(const Listed& l : surface)
  {
    const bool inner = l.side0 == l.side1;
    int ref = 0;
    switch(c.refs)
    {
    case Refs::none: ref = inner ? 7 : 0; break;
    case Refs::one_for_all: ref = 1; break;
    case Refs::one_per_face: ref = 10 + plane_index.at(plane_of(l.face)); break;
    case Refs::one_per_subdomain_pair: ref = inner ? 4 : l.side0 + l.side1; break;
    }
    if(ref == 0) continue;
    m.triangles.push_back({number[l.face[0]], number[l.face[1]], number[l.face[2]]});
    m.triangle_labels.push_back(ref);
  }
  return out;
}

} // namespace bodt_test

#endif // BODT_TEST_LABELLED_BOXES_H
