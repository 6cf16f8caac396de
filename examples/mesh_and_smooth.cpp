// Mesh a domain with CGAL's make_mesh_3, then improve the mesh with B-ODT.
//
// The one line that matters is the call to CGAL::bodt_optimize_mesh_3: it takes
// the Mesh_complex_3_in_triangulation_3 that make_mesh_3 returns, like
// CGAL::odt_optimize_mesh_3 does (the domain may be given or left out: B-ODT does
// not use it), moves boundary and feature vertices too, and keeps the volume of
// every subdomain. The parameters are in CGAL 6's chained style here;
// examples/smooth_delaunay.cpp uses CGAL 5.5's `parameters::x = v` style.
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/bodt_optimize_mesh_3.h>
#include <CGAL/make_mesh_3.h>

#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

// An ellipsoid: inside where the function is negative.
double ellipsoid(const K::Point_3& p)
{
  return p.x() * p.x() + 4 * p.y() * p.y() + 2 * p.z() * p.z() - 1;
}

int main()
{
  namespace params = CGAL::parameters;
  Domain domain = Domain::create_implicit_mesh_domain(ellipsoid, K::Sphere_3(CGAL::ORIGIN, 2.),
                                                      params::relative_error_bound = 1e-6);
  Criteria criteria(params::facet_angle = 25, params::facet_size = 0.1, params::facet_distance = 0.01,
                    params::cell_radius_edge_ratio = 3, params::cell_size = 0.1);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());

  const auto before = CGAL::BODT_3::mesh_quality(c3t3);
  const CGAL::Mesh_optimization_return_code code =
      CGAL::bodt_optimize_mesh_3(c3t3, domain, params::max_iteration_number(20).time_limit(60));
  const auto after = CGAL::BODT_3::mesh_quality(c3t3);

  std::cout << "return code " << code << "\n"   // printed by name, e.g. CANT_IMPROVE_ANYMORE
            << "min dihedral angle: " << before.min_dihedral_deg << " -> " << after.min_dihedral_deg << " deg\n"
            << "max dihedral angle: " << before.max_dihedral_deg << " -> " << after.max_dihedral_deg << " deg\n"
            << "volume: " << before.volume << " -> " << after.volume << "\n";
  return after.inverted_tets == 0 ? 0 : 1;
}
