// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_TRIANGULATION_ADAPTER_H
#define CGAL_BODT_3_INTERNAL_MESH_TRIANGULATION_ADAPTER_H

#include <CGAL/BODT_3/internal/Mesh/Cell_change_log.h>

#include <CGAL/number_utils.h>
#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// Where a cell of the triangulation belongs, for connectivity changes: a cell
/// may only be replaced by cells of its own region.
enum class Region_kind : unsigned char
{
  mesh,      // a cell of the user's mesh (in the complex of a C3T3; finite for a Triangulation_3)
  outside,   // a finite cell outside the complex: the padding of a C3T3 to the convex hull
  infinite   // a cell with the infinite vertex
};

template <class Subdomain_index>
struct Region
{
  Region_kind kind;
  Subdomain_index subdomain;   // meaningful for mesh cells

  friend bool operator==(const Region& a, const Region& b)
  {
    return a.kind == b.kind && (a.kind != Region_kind::mesh || a.subdomain == b.subdomain);
  }
  friend bool operator!=(const Region& a, const Region& b) { return !(a == b); }
};

/// The surface patch of a facet: `in_complex` false for a facet that is not a
/// boundary or interface facet of the complex.
template <class Surface_patch_index>
struct Patch
{
  bool in_complex = false;
  Surface_patch_index index = Surface_patch_index();

  friend bool operator==(const Patch& a, const Patch& b)
  {
    return a.in_complex == b.in_complex && (!a.in_complex || a.index == b.index);
  }
  friend bool operator!=(const Patch& a, const Patch& b) { return !(a == b); }
};

/// The labels of a `Mesh_complex_3_in_triangulation_3` that connectivity changes
/// must carry over: cell subdomains, boundary and interface facets with their
/// patches, and curve edges (which no change may remove). Every change goes
/// through the complex's own add/remove functions, so its counters stay right.
template <class C3T3>
class C3t3_adapter : public Cell_change_log<typename C3T3::Triangulation::Cell_handle>
{
public:
  using Triangulation = typename C3T3::Triangulation;
  using Tds = typename Triangulation::Triangulation_data_structure;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Region = internal::Region<typename C3T3::Subdomain_index>;
  using Patch = internal::Patch<typename C3T3::Surface_patch_index>;

  /// `convex_hull`: whether the triangulation's infinite cells close a real convex
  /// hull that must stay convex (a C3T3 from Mesh_3), or only close the mesh
  /// combinatorially, as for a mesh read from a file (tet_mesh_to_c3t3).
  explicit C3t3_adapter(C3T3& c3t3, bool convex_hull = true) : c3t3_(c3t3), convex_hull_(convex_hull) {}

  bool convex_hull() const { return convex_hull_; }

  Triangulation& triangulation() { return c3t3_.triangulation(); }
  const Triangulation& triangulation() const { return c3t3_.triangulation(); }
  Tds& tds() { return c3t3_.triangulation().tds(); }
  C3T3& complex() { return c3t3_; }

  Region region(Cell_handle c) const
  {
    if(c3t3_.triangulation().is_infinite(c)) return {Region_kind::infinite, typename C3T3::Subdomain_index()};
    if(c3t3_.is_in_complex(c)) return {Region_kind::mesh, c3t3_.subdomain_index(c)};
    return {Region_kind::outside, typename C3T3::Subdomain_index()};
  }

  Patch patch(Cell_handle c, int i) const
  {
    Patch p;
    p.in_complex = c3t3_.is_in_complex(c, i);
    if(p.in_complex) p.index = c3t3_.surface_patch_index(c, i);
    return p;
  }

  bool is_curve_edge(Vertex_handle a, Vertex_handle b) const { return c3t3_.is_in_complex(a, b); }

  void remove_cell(Cell_handle c) { c3t3_.remove_from_complex(c); }
  void add_cell(Cell_handle c, const Region& r)
  {
    if(r.kind == Region_kind::mesh) c3t3_.add_to_complex(c, r.subdomain);
  }
  void remove_facet(Cell_handle c, int i) { c3t3_.remove_from_complex(c, i); }
  void add_facet(Cell_handle c, int i, const Patch& p)
  {
    if(p.in_complex) c3t3_.add_to_complex(c, i, p.index);
  }

  /// A new vertex at `p`; its dimension in the complex and its index follow from
  /// where it was inserted: on the curve of edge (`a`, `b`), on a facet of `patch`,
  /// or inside `region`. A vertex on a curve gets a weight that makes its
  /// protecting ball meet its neighbours' (as `c3t3.is_valid()` asks).
  template <class Bare_point>
  Vertex_handle create_vertex(const Bare_point& p, Vertex_handle a, Vertex_handle b, const Patch& patch,
                              const Region& region)
  {
    const Vertex_handle v = tds().create_vertex();
    double weight = 0;
    if(a != Vertex_handle() && is_curve_edge(a, b))
    {
      auto cp = triangulation().geom_traits().construct_point_3_object();
      weight = (std::max)(CGAL::to_double(CGAL::squared_distance(p, cp(a->point()))),
                          CGAL::to_double(CGAL::squared_distance(p, cp(b->point()))));
      c3t3_.set_dimension(v, 1);
      set_index(v, c3t3_.curve_index(a, b));
    }
    else if(patch.in_complex)
    {
      c3t3_.set_dimension(v, 2);
      set_index(v, patch.index);
    }
    else
    {
      c3t3_.set_dimension(v, 3);
      if(region.kind == Region_kind::mesh) set_index(v, region.subdomain);
    }
    v->set_point(make_point(p, weight));
    return v;
  }

  /// After edge (`a`, `b`) was split at `e`: a curve edge becomes two.
  void split_curve(Vertex_handle a, Vertex_handle b, Vertex_handle e)
  {
    if(!is_curve_edge(a, b)) return;
    const auto curve = c3t3_.curve_index(a, b);
    c3t3_.remove_from_complex(a, b);
    c3t3_.add_to_complex(a, e, curve);
    c3t3_.add_to_complex(e, b, curve);
  }

  /// The inverse of `split_curve`, before `e` goes.
  void join_curve(Vertex_handle a, Vertex_handle e, Vertex_handle b)
  {
    if(!is_curve_edge(a, e)) return;
    const auto curve = c3t3_.curve_index(a, e);
    c3t3_.remove_from_complex(a, e);
    c3t3_.remove_from_complex(e, b);
    c3t3_.add_to_complex(a, b, curve);
  }

private:
  template <class Bare_point>
  static typename Triangulation::Point make_point(const Bare_point& p, double weight)
  {
    using Point = typename Triangulation::Point;
    if constexpr(std::is_constructible<Point, Bare_point, double>::value)
      return Point(p, weight);
    else
      return Point(p);
  }

  template <class T>
  static void set_index(Vertex_handle v, const T& x)
  {
    using Index = typename std::decay_t<decltype(*v)>::Index;
    if constexpr(std::is_constructible<Index, const T&>::value) v->set_index(Index(x));
  }

  C3T3& c3t3_;
  bool convex_hull_;
};

/// The same for a `Triangulation_3`: its finite cells are the mesh (one
/// subdomain), its convex hull the boundary; there are no patches or curves.
template <class Tr>
class Triangulation_3_adapter : public Cell_change_log<typename Tr::Cell_handle>
{
public:
  using Triangulation = Tr;
  using Tds = typename Tr::Triangulation_data_structure;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  using Region = internal::Region<int>;
  using Patch = internal::Patch<int>;

  explicit Triangulation_3_adapter(Tr& tr) : tr_(tr) {}

  bool convex_hull() const { return true; }

  Tr& triangulation() { return tr_; }
  const Tr& triangulation() const { return tr_; }
  Tds& tds() { return tr_.tds(); }

  Region region(Cell_handle c) const
  {
    return {tr_.is_infinite(c) ? Region_kind::infinite : Region_kind::mesh, 1};
  }
  Patch patch(Cell_handle, int) const { return Patch(); }
  bool is_curve_edge(Vertex_handle, Vertex_handle) const { return false; }
  void remove_cell(Cell_handle) {}
  void add_cell(Cell_handle, const Region&) {}
  void remove_facet(Cell_handle, int) {}
  void add_facet(Cell_handle, int, const Patch&) {}

  template <class Bare_point>
  Vertex_handle create_vertex(const Bare_point& p, Vertex_handle, Vertex_handle, const Patch&, const Region&)
  {
    const Vertex_handle v = tr_.tds().create_vertex();
    using Point = typename Tr::Point;
    if constexpr(std::is_constructible<Point, Bare_point, double>::value)
      v->set_point(Point(p, 0.0));
    else
      v->set_point(Point(p));
    return v;
  }
  void split_curve(Vertex_handle, Vertex_handle, Vertex_handle) {}
  void join_curve(Vertex_handle, Vertex_handle, Vertex_handle) {}

private:
  Tr& tr_;
};

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_TRIANGULATION_ADAPTER_H
