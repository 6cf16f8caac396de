// Smooth a Delaunay tetrahedralization of a point set with B-ODT: the finite
// cells are the mesh and the convex hull its boundary, which stays convex.
// The paper's "random sphere": 642 random points on the unit sphere.
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/bodt_optimize_mesh_3.h>
#include <CGAL/point_generators_3.h>

#include <iostream>
#include <iterator>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Delaunay = CGAL::Delaunay_triangulation_3<K>;

int main()
{
  CGAL::Random random(1);
  CGAL::Random_points_on_sphere_3<K::Point_3> generator(1.0, random);
  std::vector<K::Point_3> points;
  std::copy_n(generator, 642, std::back_inserter(points));
  Delaunay tr(points.begin(), points.end());

  const auto before = CGAL::BODT_3::mesh_quality(tr);
  CGAL::bodt_optimize_mesh_3(tr, CGAL::parameters::max_iteration_number = 20);
  const auto after = CGAL::BODT_3::mesh_quality(tr);
  std::cout << "min dihedral angle: " << before.min_dihedral_deg << " -> " << after.min_dihedral_deg << " deg\n"
            << "max dihedral angle: " << before.max_dihedral_deg << " -> " << after.max_dihedral_deg << " deg\n"
            << "inverted tetrahedra: " << after.inverted_tets << "\n";
  return after.inverted_tets == 0 ? 0 : 1;
}
