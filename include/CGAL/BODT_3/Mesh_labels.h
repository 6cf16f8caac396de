// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_MESH_LABELS_H
#define CGAL_BODT_3_MESH_LABELS_H

#include <type_traits>
#include <utility>

namespace CGAL {
namespace BODT_3 {

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
class C3t3_labels
{
public:
  using Triangulation = typename C3T3::Triangulation;
  using Tds = typename Triangulation::Triangulation_data_structure;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Region = BODT_3::Region<typename C3T3::Subdomain_index>;
  using Patch = BODT_3::Patch<typename C3T3::Surface_patch_index>;

  explicit C3t3_labels(C3T3& c3t3) : c3t3_(c3t3) {}

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

private:
  C3T3& c3t3_;
};

/// The same for a `Triangulation_3`: its finite cells are the mesh (one
/// subdomain), its convex hull the boundary; there are no patches or curves.
template <class Tr>
class Triangulation_labels
{
public:
  using Triangulation = Tr;
  using Tds = typename Tr::Triangulation_data_structure;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  using Region = BODT_3::Region<int>;
  using Patch = BODT_3::Patch<int>;

  explicit Triangulation_labels(Tr& tr) : tr_(tr) {}

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

private:
  Tr& tr_;
};

} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_MESH_LABELS_H
