// libFuzzer harness: a short run of the default pipeline (B-ODT sweeps, flips,
// max-min steps, insertion) on every small mesh the Medit reader accepts. The run
// must not crash, must leave every coordinate finite, must not add inverted or flat
// tetrahedra, must keep every subdomain's volume (1e-10 relative, the promise) and must add at
// most 5% vertices; otherwise the harness aborts (a finding).
#include <CGAL/BODT_3/IO/mesh_io.h>
#include <CGAL/BODT_3/mesh_quality.h>
#include <CGAL/BODT_3/smooth.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string_view>

namespace {

void require(bool ok, const char* what)
{
  if(!ok)
  {
    std::fprintf(stderr, "smoothing broke a promise: %s\n", what);
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace BODT = CGAL::BODT_3;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::ostringstream warnings;
  int version = 0;
  BODT::Tet_mesh mesh;
  try
  {
    mesh = BODT::IO::internal::parse_medit("fuzz.mesh", bytes, warnings, version);
  }
  catch(const BODT::Mesh_io_error&)
  {
    return 0;
  }
  // Small meshes only: thousands of runs a second, and the bugs live in small stars.
  if(mesh.tets.size() > 400) return 0;

  const BODT::Quality_report before = BODT::mesh_quality(mesh);
  BODT::Smoothing_options options;
  options.max_iteration_number = 3;
  // The optional steps too, on half the inputs each (chosen by the input's length).
  options.cavity_insertion = (size & 1) != 0;
  options.edge_contraction = (size & 2) != 0;
  try
  {
    BODT::smooth(mesh, options);
  }
  catch(const BODT::Mesh_io_error&)
  {
    return 0;   // a mesh the triangulation cannot hold (a non-manifold boundary), refused with its reason
  }
  const BODT::Quality_report after = BODT::mesh_quality(mesh);

  for(const auto& p : mesh.points)
    require(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()), "a coordinate is not finite");
  require(after.inverted_tets <= before.inverted_tets, "more inverted or flat tetrahedra");
  require(double(after.num_vertices) <= double(before.num_vertices) * 1.05, "more than 5% vertices added");
  for(const auto& [label, volume] : before.volume_per_subdomain)
  {
    const auto it = after.volume_per_subdomain.find(label);
    require(it != after.volume_per_subdomain.end(), "a subdomain disappeared");
    require(std::abs(it->second - volume) <= 1e-10 * std::abs(volume), "a subdomain's volume changed");
  }
  return 0;
}
