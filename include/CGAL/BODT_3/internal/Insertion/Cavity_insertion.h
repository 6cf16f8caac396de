// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_INSERTION_CAVITY_INSERTION_H
#define CGAL_BODT_3_INTERNAL_INSERTION_CAVITY_INSERTION_H

#include <CGAL/BODT_3/internal/Quality/tet_quality.h>
#include <CGAL/BODT_3/internal/Topology/replace_cells.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Where to insert an interior vertex near a bad cell, and which cells it
/// replaces (Klingner and Shewchuk's insertion with an optimized cavity, under our
/// constraints). A split of a fixed set of cells (around an edge, a face) halves
/// the angles of the cells it divides; here the cavity grows with the point: the
/// new vertex is joined to every facet of the cavity's boundary (a cone), and the
/// cavity takes in, one at a time, the cell across its worst cone that it may
/// take, up to `max_cells` cells; the best cavity seen wins.
///
/// The cavity grows only across facets that are not in the complex, into cells
/// of the same region (a subdomain), never making a facet of the complex inner:
/// so every subdomain is the same union of cells as before, its volume exact, and
/// the surface untouched. For each cavity the point is placed by a compass search
/// that maximizes the worst cone, graded so that the search finds its way: cones
/// within the extreme angles allowed by their measure, cones outside by how far,
/// inverted cones by their volume. A cavity whose cones are all positively
/// oriented is star-shaped from the point, so the cones tile it (the caller checks
/// the orientations exactly).
template <class Adapter>
class Cavity_insertion
{
public:
  using Vertex_handle = typename Adapter::Vertex_handle;
  using Cell_handle = typename Adapter::Cell_handle;
  using Point = Bare_point_t<typename Adapter::Triangulation>;

  struct Proposal
  {
    std::vector<Cell_handle> cavity;
    std::vector<std::array<int, 2>> facets;   // its boundary: (cell of the cavity, facet), the cones' bases
    Point point;
    std::vector<double> before, after;   // the cavity's cells' qualities, the cones'
    // Every cell the search read (sorted by address), whether it found a cavity or
    // not: its verdict holds while none of them is replaced.
    std::vector<Cell_handle> read;
  };

  int max_cells = 12;    // cells in a cavity at most
  int max_rounds = 60;   // of the compass search for each cavity

  Cavity_insertion(const Adapter& adapter, const Dihedral_bounds& bounds, Quality_measure measure)
    : adapter_(adapter), bounds_(bounds), measure_(measure),
      small_bound_(std::acos(std::min(1.0, bounds.cos_smallest()))),
      large_bound_(std::acos(std::max(-1.0, bounds.cos_largest())))
  {}

  /// The best cavity found from mesh cell `t` whose cones compare better, worst
  /// first, than the cells they replace; false when there is none. Two starts:
  /// t alone, and t with its neighbours across the facets it may cross (the
  /// cones over t's own facets are parts of t, no better than it).
  bool operator()(Cell_handle t, Proposal& out) const
  {
    read_ = &out.read;
    read_->assign(1, t);
    double best = -std::numeric_limits<double>::infinity();
    std::vector<Cell_handle> cavity{t};
    grow(cavity, centroid(t), best, out);
    cavity.assign(1, t);
    for(int i = 0; i < 4; ++i)
      if(crossable(t, i, cavity)) cavity.push_back(t->neighbor(i));
    if(cavity.size() > 1) grow(cavity, centroid(t), best, out);
    std::sort(read_->begin(), read_->end(), by_address);
    read_->erase(std::unique(read_->begin(), read_->end()), read_->end());
    return best > -std::numeric_limits<double>::infinity();
  }

  /// Whether a search that read the cells `read` (sorted by address, as a
  /// proposal's) read one of `replaced` (sorted by address too).
  static bool reads_any(const std::vector<Cell_handle>& read, const std::vector<Cell_handle>& replaced)
  {
    auto r = replaced.begin();
    for(Cell_handle c : read)
    {
      while(r != replaced.end() && by_address(*r, c)) ++r;
      if(r == replaced.end()) return false;
      if(*r == c) return true;
    }
    return false;
  }

  static bool by_address(Cell_handle a, Cell_handle b) { return std::less<const void*>()(&*a, &*b); }

private:
  // Grows the cavity from `cavity` (which holds p), each time across the worst
  // cone that may be crossed, placing the point anew; a cavity better than
  // `best` (its worst cone) goes into `out`.
  void grow(std::vector<Cell_handle>& cavity, Point p, double& best, Proposal& out) const
  {
    std::vector<double> before, after, searched;
    while(true)
    {
      boundary(cavity);
      p = place(p);
      searched.clear();
      after.clear();
      for(const Face& f : faces_)
      {
        double measure = 0;
        searched.push_back(cone(f, p, &measure));
        after.push_back(measure);
      }
      const bool within = *std::min_element(searched.begin(), searched.end()) >= 1;
      before.clear();
      for(Cell_handle c : cavity) before.push_back(quality(c));
      const double worst = *std::min_element(after.begin(), after.end());
      std::vector<double> a = after, b = before;
      if(within && worst > best && compare_worst_first(a, b) > 0)
      {
        best = worst;
        out.cavity = cavity;
        out.facets.clear();
        for(const Face& f : faces_) out.facets.push_back({f.in_cavity, f.index});
        out.point = p;
        out.before = before;
        out.after = after;
      }
      if(static_cast<int>(cavity.size()) >= max_cells) return;
      std::vector<std::size_t> order(faces_.size());
      for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
      // Worst first as the search sees it: a cone outside the bounds by how far.
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t x, std::size_t y) { return searched[x] < searched[y]; });
      Cell_handle next;
      for(std::size_t k : order)
        if(crossable(faces_[k].cell, faces_[k].index, cavity))
        {
          next = faces_[k].cell->neighbor(faces_[k].index);
          break;
        }
      if(next == Cell_handle()) return;
      cavity.push_back(next);
    }
  }

  // Whether the cavity may take in the cell across facet i of its cell c: a
  // finite cell of the same region, across a facet not in the complex, that
  // shares no facet of the complex with the cavity.
  bool crossable(Cell_handle c, int i, const std::vector<Cell_handle>& cavity) const
  {
    const Cell_handle n = c->neighbor(i);
    read_->push_back(n);
    if(adapter_.triangulation().is_infinite(n) || !(adapter_.region(n) == adapter_.region(c)) ||
       adapter_.patch(c, i).in_complex)
      return false;
    if(std::find(cavity.begin(), cavity.end(), n) != cavity.end()) return false;
    return joins(n, cavity);
  }

  struct Face
  {
    Cell_handle cell;
    int index;
    int in_cavity;   // the cell's place in the cavity
  };

  Point point(Vertex_handle v) const { return bare_point(adapter_.triangulation(), v); }

  Point centroid(Cell_handle c) const
  {
    double x = 0, y = 0, z = 0;
    for(int k = 0; k < 4; ++k)
    {
      const Point q = point(c->vertex(k));
      x += q.x();
      y += q.y();
      z += q.z();
    }
    return Point(x / 4, y / 4, z / 4);
  }

  double quality(Cell_handle c) const
  {
    return tet_quality(measure_, point(c->vertex(0)), point(c->vertex(1)), point(c->vertex(2)), point(c->vertex(3)));
  }

  // Cell n may join the cavity if no facet it shares with a cell of the cavity is in the complex.
  bool joins(Cell_handle n, const std::vector<Cell_handle>& cavity) const
  {
    for(int i = 0; i < 4; ++i)
    {
      read_->push_back(n->neighbor(i));
      if(std::find(cavity.begin(), cavity.end(), n->neighbor(i)) != cavity.end() && adapter_.patch(n, i).in_complex)
        return false;
    }
    return true;
  }

  // The facets of the cavity's boundary, in the order of its cells.
  void boundary(const std::vector<Cell_handle>& cavity) const
  {
    faces_.clear();
    for(std::size_t k = 0; k < cavity.size(); ++k)
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = cavity[k]->neighbor(i);
        read_->push_back(n);
        if(std::find(cavity.begin(), cavity.end(), n) == cavity.end())
          faces_.push_back({cavity[k], i, static_cast<int>(k)});
      }
  }

  std::array<Point, 4> cone_points(const Face& f, const Point& p) const
  {
    std::array<Point, 4> q;
    for(int k = 0; k < 4; ++k) q[static_cast<std::size_t>(k)] = k == f.index ? p : point(f.cell->vertex(k));
    return q;
  }

  double measure_of(const std::array<Point, 4>& q) const { return tet_quality(measure_, q[0], q[1], q[2], q[3]); }

  // The cone from p over facet f, as the cell of f with the vertex opposite f
  // replaced by p, for the search: within the bounds, one plus its measure;
  // outside, how far its smallest and largest angles are in, each over the room
  // the bounds leave it (1 at the bound); an inverted cone below all, by its volume.
  // Its measure goes to `measure` if given.
  double cone(const Face& f, const Point& p, double* measure = nullptr) const
  {
    const std::array<Point, 4> q = cone_points(f, p);
    const double v = measure_of(q);
    if(measure) *measure = v;
    if(v < 0) return -4 + signed_shape(q[0], q[1], q[2], q[3]);
    const double sine = measure_ == Quality_measure::min_dihedral_sine ? v : 0.0;
    if(bounds_.safe(sine)) return 1 + v;
    const auto c = dihedral_cosines(q[0], q[1], q[2], q[3]);   // computed once, for both
    if(bounds_.contains(c, sine)) return 1 + v;
    const double smallest = std::acos(std::min(1.0, *std::max_element(c.begin(), c.end())));
    const double largest = std::acos(std::max(-1.0, *std::min_element(c.begin(), c.end())));
    return std::min(smallest / small_bound_, (pi - largest) / (pi - large_bound_));
  }

  // The signed volume over the cube of the root mean square edge, in [-1, 1]
  // (about 0.1 for a regular tetrahedron): how far an inverted cone is from turning.
  static double signed_shape(const Point& a, const Point& b, const Point& c, const Point& d)
  {
    const auto u = b - a, v = c - a, w = d - a;
    const double det = u * CGAL::cross_product(v, w);
    const double l = (u.squared_length() + v.squared_length() + w.squared_length() + (c - b).squared_length() +
                      (d - b).squared_length() + (d - c).squared_length()) / 6;
    return std::max(-1.0, std::min(1.0, det / (l * std::sqrt(l))));
  }

  // The worst cone from p, and its face in `worst`; or, once it is known to be
  // at most `floor`, some value at most `floor`: a point no better than the best
  // so far is left at its first cone that says so. Face `first` (the one that
  // limited the search's point) is tried first.
  double worst_cone(const Point& p, std::size_t first, std::size_t& worst,
                    double floor = -std::numeric_limits<double>::infinity()) const
  {
    worst = first;
    double w = std::numeric_limits<double>::infinity();
    for(std::size_t n = 0; n < faces_.size(); ++n)
    {
      const std::size_t k = n == 0 ? first : (n <= first ? n - 1 : n);
      if(const double c = cone(faces_[k], p); c < w)
      {
        w = c;
        worst = k;
        if(w <= floor) break;
      }
    }
    return w;
  }

  // Compass search from p for the largest worst cone: six axis and eight diagonal
  // directions, the step halved when none improves.
  Point place(Point p) const
  {
    double len = std::numeric_limits<double>::infinity();
    for(const Face& f : faces_)
      for(int a = 0; a < 4; ++a)
        for(int b = a + 1; b < 4; ++b)
          if(a != f.index && b != f.index)
            len = std::min(len, std::sqrt(CGAL::squared_distance(point(f.cell->vertex(a)), point(f.cell->vertex(b)))));
    double h = 0.25 * len;
    const double stop = 1e-4 * len;
    static const double d = 1 / std::sqrt(3.0);
    static const double dirs[14][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},   {0, -1, 0}, {0, 0, 1},
                                       {0, 0, -1}, {d, d, d},  {d, d, -d},  {d, -d, d}, {d, -d, -d},
                                       {-d, d, d}, {-d, d, -d}, {-d, -d, d}, {-d, -d, -d}};
    std::size_t limiting = 0;   // the face of the worst cone at p
    double value = worst_cone(p, 0, limiting);
    for(int round = 0; round < max_rounds && h > stop; ++round)
    {
      Point best = p;
      double best_value = value;
      std::size_t best_limiting = limiting;
      for(const auto& dir : dirs)
      {
        const Point q(p.x() + h * dir[0], p.y() + h * dir[1], p.z() + h * dir[2]);
        std::size_t worst = 0;
        const double v = worst_cone(q, limiting, worst, best_value);
        if(v > best_value)
        {
          best_value = v;
          best = q;
          best_limiting = worst;
        }
      }
      if(best_value > value)
      {
        p = best;
        value = best_value;
        limiting = best_limiting;
      }
      else
        h *= 0.5;
    }
    return p;
  }

  const Adapter& adapter_;
  const Dihedral_bounds& bounds_;
  Quality_measure measure_;
  double small_bound_, large_bound_;   // the bounds' angles, in radians
  mutable std::vector<Face> faces_;
  mutable std::vector<Cell_handle>* read_ = nullptr;   // the proposal's, during a search
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_INSERTION_CAVITY_INSERTION_H
