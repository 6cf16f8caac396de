// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_INTERNAL_MESH_FLAT_VIEW_H
#define CGAL_BODT_3_INTERNAL_MESH_FLAT_VIEW_H

#include <CGAL/BODT_3/internal/Utilities/Handle_index_map.h>
#include <CGAL/BODT_3/internal/Utilities/Index_shift.h>
#include <CGAL/BODT_3/internal/Mesh/Triangulation_adapter.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>
#include <CGAL/BODT_3/internal/Mesh/Flat_mesh.h>
#include <CGAL/BODT_3/internal/Utilities/first_touch.h>
#include <CGAL/BODT_3/internal/Utilities/Thread_workers.h>
#include <CGAL/BODT_3/internal/Classification/Vertex_classification.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace BODT_3 {
namespace internal {

/// The flat view (`Flat_mesh`) of a 3D triangulation (`Triangulation_3`,
/// `Delaunay_triangulation_3`, `Regular_triangulation_3`, or the triangulation of
/// a C3T3) that the smoothing sweeps work on, with stable vertex ids (the order of
/// the finite vertices, vertices added later appended). `Adapter` (Triangulation_adapter.h)
/// says which cells are the mesh and their subdomains. The view never changes the
/// connectivity: flips and insertion change the triangulation, and `refresh`
/// re-reads its cells. Positions go back with `Vertex::set_point`, keeping the
/// weight of weighted points.
template <class Adapter>
class Flat_view
{
public:
  using Tr = typename Adapter::Triangulation;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  using Bare_point = Bare_point_t<Tr>;
  using Kernel = typename CGAL::Kernel_traits<Bare_point>::Kernel;
  using Mesh = Flat_mesh<Kernel>;

  /// `threads`: as `Smoothing_options::threads`; the view does not depend on it.
  explicit Flat_view(Adapter& adapter, int threads = 1) : adapter_(adapter), workers_(threads)
  {
    if(adapter.triangulation().dimension() != 3)
      throw std::invalid_argument("B-ODT smoothing needs a triangulation of dimension 3");
    mesh_.threads = threads;
    refresh();
  }

  Mesh& mesh() { return mesh_; }
  const Mesh& mesh() const { return mesh_; }
  const Adapter& adapter() const { return adapter_; }
  const std::vector<Cell_handle>& cells() const { return cells_; }
  /// How many cells the last read took from the triangulation: all of them, or
  /// the new ones when it followed the changes.
  std::size_t cells_read() const { return cells_read_; }
  const std::vector<Vertex_handle>& vertices() const { return handles_; }

  /// Where the last `refresh` put the cells of the read before it: after a read of
  /// the changes, the kept cells moved as `Index_shift::relocate` with `shift` and
  /// `kept_before` moves an array (their vertices, in order, unchanged) and the new
  /// cells are at `fresh`; after a whole read (`whole`), any cell may be anywhere.
  struct Cell_moves
  {
    bool whole = true;
    Index_shift shift;
    std::vector<std::size_t> kept_before;
    std::vector<int> fresh;
  };
  const Cell_moves& last_cell_moves() const { return moves_; }

  int index(Vertex_handle v) const
  {
    const int i = index_.find(v);
    if(i < 0) throw std::out_of_range("vertex not in the view");
    return i;
  }

  /// From now on, `refresh()` re-reads only the cells that the adapter's change
  /// log (Cell_change_log) names and the adjacency around them: every change of
  /// the cells must then go through `replace_cells`. Call it right after a read.
  void follow_changes()
  {
    adapter_.start_logging();
    follows_changes_ = true;
  }

  /// Re-reads the cells (and any new vertex) of the triangulation, with their
  /// regions, the hull checks and the incidences; the arrays are those a first
  /// read gives.
  void refresh()
  {
    read_vertices();
    std::vector<Cell_handle> changed;
    adapter_.take_changes(changed);
    // Looking a logged cell up walks the container's blocks (a few hundred), and
    // many changes leave few neighbour indices unshifted: past a sixteenth of the
    // cells (a choice, not tuned), the whole read.
    if(follows_changes_ && slots_known_ && changed.size() <= cells_.size() / 16)
      read_changed_cells(changed);   // in place: the incidences keep their pages
    else
    {
      // The incidences are derived again below: freed first, so that they are not
      // held with the old and the new cell arrays of the whole read at once.
      mesh_.release_incidences();
      moves_ = Cell_moves();
      read_cells();
      cells_read_ = cells_.size();
    }
    mesh_.hull_checks.clear();
    if(adapter_.convex_hull()) add_hull_checks();
    mesh_.build_incidences();
  }

  /// Forgets the vertex of index `i`, which the triangulation no longer has (an
  /// edge contraction removed it): the index stays, with no cell, and is never
  /// given to another vertex, so that indices stay stable ids.
  void forget(int i) { handles_[static_cast<std::size_t>(i)] = Vertex_handle(); }

  /// Writes the positions of `mesh()` back into the triangulation.
  void write_back()
  {
    for(std::size_t i = 0; i < handles_.size(); ++i)
      if(handles_[i] != Vertex_handle()) set_bare_point(adapter_.triangulation(), handles_[i], mesh_.points[i]);
  }

  /// Re-reads the positions from the triangulation (after moves made on it
  /// directly); appends to `moved`, when given, the vertices whose position changed.
  void read_points(std::vector<int>* moved = nullptr)
  {
    for(std::size_t i = 0; i < handles_.size(); ++i)
    {
      if(handles_[i] == Vertex_handle()) continue;
      const Bare_point p = bare_point(adapter_.triangulation(), handles_[i]);
      if(moved && p != mesh_.points[i]) moved->push_back(static_cast<int>(i));
      mesh_.points[i] = p;
    }
  }

private:
  // Any vertex not in the view yet, appended.
  void read_vertices()
  {
    Tr& tr = adapter_.triangulation();
    auto cp = tr.geom_traits().construct_point_3_object();
    // Made at their size: by push_back, a few inserted vertices would double them.
    const std::size_t known = static_cast<std::size_t>(
        std::count_if(handles_.begin(), handles_.end(), [](Vertex_handle v) { return v != Vertex_handle(); }));
    const std::size_t size = handles_.size() + (tr.number_of_vertices() - known);
    handles_.reserve(size);
    mesh_.points.reserve(size);
    if(handles_.empty()) index_.reset(size);   // a first read: the map at its size, not grown by doubling
    // The map's slots of the vertex a few ahead are loaded meanwhile (a cache miss each).
    auto ahead = tr.finite_vertices_begin();
    for(int k = 0; k < 16 && ahead != tr.finite_vertices_end(); ++k) ++ahead;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    {
      if(ahead != tr.finite_vertices_end()) index_.prefetch(ahead++);
      // A new vertex may live where a removed one did: it gets a new index.
      const int known = index_.find(v);
      if(known >= 0 && handles_[known] != Vertex_handle()) continue;
      index_.assign(v, static_cast<int>(handles_.size()));
      handles_.push_back(v);
      mesh_.points.push_back(cp(v->point()));
    }
  }

  // For each hull facet and each of its three neighbours on the hull, the far
  // vertex of the neighbour must stay on the inner side of the facet's plane;
  // checks that do not hold now (a hull that is not convex there) are left out.
  void add_hull_checks()
  {
    Tr& tr = adapter_.triangulation();
    const Vertex_handle inf = tr.infinite_vertex();
    std::vector<Cell_handle> hull;
    tr.tds().incident_cells(inf, std::back_inserter(hull));
    for(const Cell_handle& c : hull)
    {
      const int i = c->index(inf);
      const Cell_handle fc = c->neighbor(i);
      const int j = fc->index(c);
      const auto& o = internal::facet_opposite[j];
      // Swap two vertices of facet_opposite[j] so that the interior is on the positive side.
      const int a = index(fc->vertex(o[0])), b = index(fc->vertex(o[2])), d = index(fc->vertex(o[1]));
      for(int k = 0; k < 4; ++k)
      {
        if(k == i) continue;
        const Cell_handle nc = c->neighbor(k);
        const Vertex_handle w = nc->vertex(nc->index(c));
        if(w == inf) continue;
        const int wi = index(w);
        if(CGAL::orientation(mesh_.points[a], mesh_.points[b], mesh_.points[d], mesh_.points[wi]) !=
           CGAL::NEGATIVE)
          mesh_.hull_checks.push_back({a, b, d, wi});
      }
    }
  }

  // The cells, with their vertices, regions and neighbours, in the order of the
  // triangulation's container. A pass that changes cells replaces them and
  // leaves the others where they are: a cell at the same address as at the last
  // read, with the same vertices, is the same tetrahedron, and keeps its vertex
  // indices and the neighbours that stayed (the two cells on a triangle are the
  // same as long as both are). Only the new cells and the neighbours of the old
  // ones across a changed triangle are looked up, in a map of the new cells; the
  // arrays are those a first read makes.
  void read_cells()
  {
    Tr& tr = adapter_.triangulation();
    std::vector<Cell_handle> before;
    before.swap(cells_);
    const int threads = workers_.threads();
    // Room for a few more, which the next re-reads add in place (read_changed_cells);
    // push_back alone would hold up to twice their number.
    // All cells, infinite ones too: number_of_finite_cells() would count them one by one.
    reserve_fresh(cells_, with_room(tr.number_of_cells()), threads);
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) cells_.push_back(c);
    read_slots();
    const std::size_t nc = cells_.size();
    std::vector<std::array<int, 4>> cells_before;
    cells_before.swap(mesh_.cells);
    std::vector<int> neighbor_before;
    neighbor_before.swap(mesh_.neighbor);
    std::vector<int> now = same_slots(before);   // per cell before: its index now, or -1
    std::vector<Cell_handle>().swap(before);

    reserve_fresh(mesh_.cells, with_room(nc), threads);
    mesh_.cells.resize(nc);
    reserve_fresh(mesh_.in_mesh, with_room(nc), threads);
    mesh_.in_mesh.resize(nc);
    reserve_fresh(mesh_.subdomain, with_room(nc), threads);
    mesh_.subdomain.resize(nc);
    reserve_fresh(mesh_.neighbor, 4 * with_room(nc), threads);
    mesh_.neighbor.assign(4 * nc, unknown_neighbor);
    // A slot that holds a new cell, or a cell changed in place, has other vertices: it is new.
    std::vector<char> is_new;
    assign_fresh(is_new, nc, char(1), threads);
    const int n_before = static_cast<int>(now.size());
    workers_.for_each(0, n_before, [&](char&, int j) {
      const int k = now[static_cast<std::size_t>(j)];
      if(k < 0) return;
      const Cell_handle c = cells_[static_cast<std::size_t>(k)];
      const std::array<int, 4>& q = cells_before[static_cast<std::size_t>(j)];
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != handles_[static_cast<std::size_t>(q[i])])
        {
          now[static_cast<std::size_t>(j)] = -1;
          return;
        }
      mesh_.cells[k] = q;
      is_new[static_cast<std::size_t>(k)] = 0;
    }, 1024);
    std::vector<int> fresh;
    for(std::size_t k = 0; k < nc; ++k)
      if(is_new[k]) fresh.push_back(static_cast<int>(k));
    std::vector<char>().swap(is_new);
    Handle_index_map<Cell_handle> fresh_index;
    fresh_index.reset(fresh.size());
    // Each insertion misses the cache (a first read inserts every cell): the slots of
    // the insertions a few ahead are loaded meanwhile.
    constexpr std::size_t ahead = 16;
    for(std::size_t f = 0; f < fresh.size(); ++f)
    {
      if(f + ahead < fresh.size()) fresh_index.prefetch(cells_[static_cast<std::size_t>(fresh[f + ahead])]);
      fresh_index.insert(cells_[static_cast<std::size_t>(fresh[f])], fresh[f]);
    }

    // The cells kept: a neighbour that stayed is where it went; any other is new
    // (it then learns this cell across the same triangle) or infinite.
    workers_.for_each(0, n_before, [&](char&, int j) {
      const int k = now[static_cast<std::size_t>(j)];
      if(k < 0) return;
      const Cell_handle c = cells_[static_cast<std::size_t>(k)];
      read_region(k, c);
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        const int o = neighbor_before[4 * static_cast<std::size_t>(j) + i];
        const int m = o >= 0 ? now[static_cast<std::size_t>(o)] : -1;
        int& entry = mesh_.neighbor[4 * static_cast<std::size_t>(k) + i];
        if(m >= 0 && cells_[static_cast<std::size_t>(m)] == n)
          entry = m;
        else if((entry = fresh_index.find(n)) >= 0)
          mesh_.neighbor[4 * static_cast<std::size_t>(entry) + n->index(c)] = k;
        else
          entry = checked_infinite(n);
      }
    }, 1024);
    std::vector<std::array<int, 4>>().swap(cells_before);
    std::vector<int>().swap(neighbor_before);
    std::vector<int>().swap(now);
    // The new cells: their vertices, and the neighbours not set from the other side.
    workers_.for_each(0, static_cast<int>(fresh.size()), [&](char&, int f) {
      const int k = fresh[static_cast<std::size_t>(f)];
      const Cell_handle c = cells_[static_cast<std::size_t>(k)];
      mesh_.cells[k] = {index(c->vertex(0)), index(c->vertex(1)), index(c->vertex(2)), index(c->vertex(3))};
      read_region(k, c);
      for(int i = 0; i < 4; ++i)
      {
        int& entry = mesh_.neighbor[4 * static_cast<std::size_t>(k) + i];
        if(entry != unknown_neighbor) continue;
        const Cell_handle n = c->neighbor(i);
        entry = fresh_index.find(n);
        if(entry < 0) entry = checked_infinite(n);
      }
    }, 256);
  }

  // The container slot of every cell read, for `read_changed_cells`. The slots
  // follow the cells' order; consecutive cells in consecutive slots of a block
  // need no lookup, others a walk over the blocks (`Compact_container::index`).
  void read_slots()
  {
    const auto& container = adapter_.triangulation().tds().cells();
    slots_known_ = container.capacity() < std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t>().swap(slots_);
    if(!slots_known_) return;
    reserve_fresh(slots_, with_room(cells_.size()), workers_.threads());
    slots_.resize(cells_.size());
    using Cell = typename Tr::Triangulation_data_structure::Cell;
    const Cell* last = nullptr;
    for(std::size_t k = 0; k < cells_.size(); ++k)
    {
      const Cell* c = &*cells_[k];
      slots_[k] = last && c == last + 1 ? slots_[k - 1] + 1 : static_cast<std::uint32_t>(container.index(cells_[k]));
      last = c;
    }
  }

  // The read after changes that went through `replace_cells`, whose cells the
  // adapter logged (`changed`: removed or created, by slot; a slot may be named
  // twice, or hold nothing now). The cells in other slots are those of the last
  // read, with the same vertices, regions and neighbours but across a changed
  // facet; the new ones go where their slots put them in the container's order,
  // so that the arrays are those of a whole read. The arrays are changed in
  // place: on a virtual machine, fresh pages for new arrays cost more than the
  // whole read of a few changes.
  void read_changed_cells(const std::vector<Cell_handle>& changed)
  {
    Tr& tr = adapter_.triangulation();
    const auto& container = tr.tds().cells();
    std::vector<std::pair<std::uint32_t, Cell_handle>> slots;
    slots.reserve(changed.size());
    for(const Cell_handle& c : changed) slots.push_back({static_cast<std::uint32_t>(container.index(c)), c});
    std::sort(slots.begin(), slots.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    slots.erase(std::unique(slots.begin(), slots.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
                slots.end());
    // The cells of the last read in a changed slot are gone; the finite cells now
    // in one are new. A new cell goes before the first cell of the last read with
    // a larger slot (`before`, an old index).
    moves_.whole = false;
    Index_shift& shift = moves_.shift;
    shift.gone.clear();
    std::vector<std::pair<std::uint32_t, Cell_handle>> fresh;
    std::vector<std::size_t> before;
    for(const auto& [slot, c] : slots)
    {
      const std::size_t at = static_cast<std::size_t>(std::lower_bound(slots_.begin(), slots_.end(), slot) - slots_.begin());
      if(at < slots_.size() && slots_[at] == slot) shift.gone.push_back(static_cast<int>(at));
      if(container.is_used(c) && !tr.is_infinite(c))
      {
        fresh.push_back({slot, c});
        before.push_back(at);
      }
    }
    const std::size_t n_before = cells_.size();
    shift.prepare(before, n_before);

    // The kept cells next to a gone one, found through the gone cells' neighbours
    // before these are overwritten: a new cell's neighbour that is not new is one
    // of them, or infinite, or (after a change of the hull) a cell that was next
    // to an infinite cell that went.
    Handle_index_map<Cell_handle> border;
    border.reset(4 * shift.gone.size());
    std::vector<int> border_cells;
    for(int j : shift.gone)
      for(int i = 0; i < 4; ++i)
      {
        const int o = mesh_.neighbor[4 * static_cast<std::size_t>(j) + i];
        if(o < 0 || shift.is_gone(o)) continue;
        const int k = shift.now(o);
        if(border.insert(cells_[static_cast<std::size_t>(o)], k)) border_cells.push_back(k);
      }

    // Where the new cells go: after the kept cells before them, and the new ones before.
    std::vector<std::size_t>& kept_before = moves_.kept_before;
    kept_before.assign(fresh.size(), 0);
    for(std::size_t f = 0; f < fresh.size(); ++f)
      kept_before[f] = before[f] - shift.gone_before(before[f]);
    const std::size_t nc = n_before - shift.gone.size() + fresh.size();
    shift.relocate(cells_, 1, kept_before, nc);
    shift.relocate(slots_, 1, kept_before, nc);
    shift.relocate(mesh_.cells, 1, kept_before, nc);
    shift.relocate(mesh_.in_mesh, 1, kept_before, nc);
    shift.relocate(mesh_.subdomain, 1, kept_before, nc);
    shift.relocate(mesh_.neighbor, 4, kept_before, nc);
    std::vector<int>& fresh_at = moves_.fresh;
    fresh_at.assign(fresh.size(), 0);
    for(std::size_t f = 0; f < fresh.size(); ++f)
    {
      fresh_at[f] = static_cast<int>(kept_before[f] + f);
      cells_[static_cast<std::size_t>(fresh_at[f])] = fresh[f].second;
      slots_[static_cast<std::size_t>(fresh_at[f])] = fresh[f].first;
    }
    // The kept cells' neighbours, as indices of now; one gone is learnt below.
    workers_.for_each(0, static_cast<int>(nc), [&](char&, int k) {
      for(int i = 0; i < 4; ++i)
      {
        int& entry = mesh_.neighbor[4 * static_cast<std::size_t>(k) + i];
        if(entry >= 0) entry = shift.is_gone(entry) ? unknown_neighbor : shift.now(entry);
      }
    }, 4096);

    cells_read_ = fresh.size();
    Handle_index_map<Cell_handle> fresh_index;
    fresh_index.reset(fresh.size());
    for(std::size_t f = 0; f < fresh.size(); ++f) fresh_index.insert(fresh[f].second, fresh_at[f]);
    // The new cells, on one thread (they are few): their vertices, regions and
    // neighbours, and theirs as neighbours of the kept cells.
    for(std::size_t f = 0; f < fresh.size(); ++f)
    {
      const int k = fresh_at[f];
      const Cell_handle c = fresh[f].second;
      mesh_.cells[k] = {index(c->vertex(0)), index(c->vertex(1)), index(c->vertex(2)), index(c->vertex(3))};
      read_region(k, c);
      for(int i = 0; i < 4; ++i)
      {
        const Cell_handle n = c->neighbor(i);
        int m = fresh_index.find(n);
        if(m < 0 && !tr.is_infinite(n))
        {
          m = border.find(n);
          if(m < 0) m = slot_index(n);
          mesh_.neighbor[4 * static_cast<std::size_t>(m) + n->index(c)] = k;
        }
        mesh_.neighbor[4 * static_cast<std::size_t>(k) + i] = m;
      }
    }
    // A kept cell whose neighbour went with no new finite cell there is on the hull now.
    for(int k : border_cells)
      for(int i = 0; i < 4; ++i)
      {
        int& entry = mesh_.neighbor[4 * static_cast<std::size_t>(k) + i];
        if(entry == unknown_neighbor) entry = checked_infinite(cells_[static_cast<std::size_t>(k)]->neighbor(i));
      }
  }

  // The index of a cell of the view, by its slot.
  int slot_index(Cell_handle c) const
  {
    const auto slot = static_cast<std::uint32_t>(adapter_.triangulation().tds().cells().index(c));
    const auto at = std::lower_bound(slots_.begin(), slots_.end(), slot);
    if(at == slots_.end() || *at != slot || cells_[static_cast<std::size_t>(at - slots_.begin())] != c)
      throw std::logic_error("Flat_view: a neighbour not in the view");
    return static_cast<int>(at - slots_.begin());
  }

  static constexpr int unknown_neighbor = -2;

  void read_region(int k, Cell_handle c)
  {
    const auto r = adapter_.region(c);
    mesh_.in_mesh[k] = r.kind == Region_kind::mesh ? 1 : 0;
    mesh_.subdomain[k] = r.kind == Region_kind::mesh ? static_cast<int>(r.subdomain) : 0;
  }

  // -1 for a neighbour outside the view, which can only be an infinite cell.
  int checked_infinite(Cell_handle n) const
  {
    if(!adapter_.triangulation().is_infinite(n)) throw std::logic_error("Flat_view: a neighbour not in the view");
    return -1;
  }

  // For each cell of the last read (`before`), its index in this one if its slot
  // still holds a finite cell, else -1. Both lists follow the container's slots,
  // whose order the cells that stay keep: one walk pairs them.
  std::vector<int> same_slots(const std::vector<Cell_handle>& before) const
  {
    const Tr& tr = adapter_.triangulation();
    std::vector<int> now(before.size(), -1);
    std::size_t j = 0, k = 0;
    while(j < before.size() && k < cells_.size())
    {
      if(before[j] == cells_[k])
        now[j++] = static_cast<int>(k++);
      else if(tr.tds().cells().is_used(before[j]) && !tr.is_infinite(before[j]))
        ++k;   // cells_[k] is new, in a slot before that of before[j], which is still there
      else
        ++j;   // before[j] is gone (or no longer finite)
    }
    return now;
  }

  Adapter& adapter_;
  Thread_workers<char> workers_;
  Mesh mesh_;
  std::vector<Vertex_handle> handles_;
  std::vector<Cell_handle> cells_;
  std::vector<std::uint32_t> slots_;   // per cell, its slot in the container (read_slots)
  bool slots_known_ = false;
  bool follows_changes_ = false;
  std::size_t cells_read_ = 0;
  Cell_moves moves_;
  Handle_index_map<Vertex_handle> index_;
};

/// What a `Mesh_complex_3_in_triangulation_3` knows of its features: vertex
/// dimensions, curve edges, corners and surface patches, by view vertex id. The
/// vertices of facets of the complex between two cells of the same subdomain (an
/// embedded surface) count as corners: they stay fixed, so the surface does.
template <class C3T3, class View>
Feature_hints c3t3_feature_hints(const C3T3& c3t3, const View& view)
{
  Feature_hints hints;
  hints.dimension.resize(view.vertices().size());
  for(std::size_t v = 0; v < view.vertices().size(); ++v)
    hints.dimension[v] = static_cast<signed char>(c3t3.in_dimension(view.vertices()[v]));
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
    hints.feature_edges.push_back({view.index(e->first->vertex(e->second)), view.index(e->first->vertex(e->third))});
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    hints.corners.push_back(view.index(v));
  std::map<typename C3T3::Surface_patch_index, int> patch_ids;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    const auto id = patch_ids.emplace(c3t3.surface_patch_index(*f), static_cast<int>(patch_ids.size())).first->second;
    std::array<int, 3> t;
    for(int k = 0, m = 0; k < 4; ++k)
      if(k != f->second) t[m++] = view.index(f->first->vertex(k));
    hints.facet_patches.push_back({t, id});
    // A facet between two cells of one region is an embedded surface, which no
    // volume or interface rule holds in place: its vertices stay where they are.
    if(view.adapter().region(f->first) == view.adapter().region(f->first->neighbor(f->second)))
      hints.corners.insert(hints.corners.end(), t.begin(), t.end());
  }
  return hints;
}

} // namespace internal
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_INTERNAL_MESH_FLAT_VIEW_H
