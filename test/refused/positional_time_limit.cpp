// Must not compile: a bare number after the mesh is neither a domain nor a named
// parameter (it used to be taken as time_limit silently).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/bodt_optimize_mesh_3.h>
int main()
{
  CGAL::Delaunay_triangulation_3<CGAL::Exact_predicates_inexact_constructions_kernel> tr;
  CGAL::bodt_optimize_mesh_3(tr, 10.0);
}
