// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks shared by the tests that change the connectivity of a C3T3 built from a
// Tet_mesh (flips, insertion, local smoothing).
#ifndef BODT_TEST_C3T3_CHECKS_H
#define BODT_TEST_C3T3_CHECKS_H

#include "exact_volumes.h"

#include <CGAL/BODT_3/Tet_mesh_conversion.h>
#include <CGAL/BODT_3/internal/Utilities/bare_point.h>

#include <gtest/gtest.h>

#include <map>

namespace bodt_test {

using File_c3t3 = CGAL::BODT_3::Tet_mesh_c3t3;

inline CGAL::BODT_3::Tet_mesh::Point bare(const File_c3t3& c3t3, File_c3t3::Vertex_handle v)
{
  return CGAL::BODT_3::internal::bare_point(c3t3.triangulation(), v);
}

// The triangulation is combinatorially valid, every finite cell is positively
// oriented (exact predicate), and the complex's counters match its content.
inline void expect_valid(const File_c3t3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  EXPECT_TRUE(tr.tds().is_valid());
  std::size_t bad = 0, in_complex = 0, facets = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
  {
    if(CGAL::orientation(bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)), bare(c3t3, c->vertex(2)),
                         bare(c3t3, c->vertex(3))) != CGAL::POSITIVE)
      ++bad;
    if(c3t3.is_in_complex(c)) ++in_complex;
  }
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(c3t3.is_in_complex(c, i))
      {
        ++facets;
        EXPECT_TRUE(c3t3.is_in_complex(c->neighbor(i), c->neighbor(i)->index(c)));
        EXPECT_EQ(c3t3.surface_patch_index(c, i),
                  c3t3.surface_patch_index(c->neighbor(i), c->neighbor(i)->index(c)));
      }
  EXPECT_EQ(bad, 0u);
  EXPECT_EQ(in_complex, c3t3.number_of_cells_in_complex());
  EXPECT_EQ(facets, 2 * c3t3.number_of_facets_in_complex());
}

// Every subdomain's volume, exactly, from the cells of the complex.
inline std::map<int, Exact> exact_subdomain_volumes(const File_c3t3& c3t3)
{
  std::map<int, Exact> v;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    v[c3t3.subdomain_index(c)] += exact_det(bare(c3t3, c->vertex(0)), bare(c3t3, c->vertex(1)), bare(c3t3, c->vertex(2)),
                                            bare(c3t3, c->vertex(3))) / 6;
  return v;
}

} // namespace bodt_test

#endif // BODT_TEST_C3T3_CHECKS_H
