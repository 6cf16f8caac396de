// Must not compile: sliver_bound belongs to perturb_mesh_3 and exude_mesh_3.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/bodt_optimize_mesh_3.h>
int main()
{
  CGAL::Delaunay_triangulation_3<CGAL::Exact_predicates_inexact_constructions_kernel> tr;
  CGAL::bodt_optimize_mesh_3(tr, CGAL::parameters::sliver_bound = 10);
}
