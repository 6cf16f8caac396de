// Must not compile: freezing is decided by freeze_bound alone (test parameters_refused_do_freeze).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/bodt_optimize_mesh_3.h>
int main()
{
  CGAL::Delaunay_triangulation_3<CGAL::Exact_predicates_inexact_constructions_kernel> tr;
  CGAL::bodt_optimize_mesh_3(tr, CGAL::parameters::time_limit = 10, CGAL::parameters::do_freeze = false);
}
