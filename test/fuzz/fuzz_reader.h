// Shared by the reader harnesses: parse the bytes libFuzzer gives; a Mesh_io_error is
// a correct answer to bad input. A mesh that parses must survive a round trip: written
// in the format it was read from and parsed again, it gives the same mesh, or the
// harness aborts (a finding).
#ifndef BODT_FUZZ_READER_H
#define BODT_FUZZ_READER_H

#include <CGAL/BODT_3/IO/mesh_io.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

namespace bodt_fuzz {

using CGAL::BODT_3::Tet_mesh;

inline void require(bool ok, const char* what)
{
  if(!ok)
  {
    std::fprintf(stderr, "round trip changed %s\n", what);
    std::abort();
  }
}

/// `b`, read back from what was written of `a`, holds the same mesh (corners only where the format keeps them).
inline void require_same(const Tet_mesh& a, const Tet_mesh& b, bool corners, bool refs)
{
  require(a.points == b.points, "the points");
  require(a.tets == b.tets, "the tetrahedra");
  require(a.tet_labels == b.tet_labels, "the tetrahedron labels");
  require(a.triangles == b.triangles, "the triangles");
  require(a.triangle_labels == b.triangle_labels, "the triangle labels");
  require(a.edges == b.edges, "the edges");
  require(a.edge_labels == b.edge_labels, "the edge labels");
  if(corners) require(a.corners == b.corners, "the corners");
  if(refs) require(a.vertex_refs == b.vertex_refs, "the vertex references");
}

/// Runs `parse(bytes)`; when it gives a mesh, `round_trip(mesh)` checks it.
template <class Parse, class Round_trip>
int run(const std::uint8_t* data, std::size_t size, Parse parse, Round_trip round_trip)
{
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  Tet_mesh mesh;
  try
  {
    mesh = parse(bytes);
  }
  catch(const CGAL::BODT_3::Mesh_io_error&)
  {
    return 0;
  }
  round_trip(mesh);
  return 0;
}

} // namespace bodt_fuzz

#endif // BODT_FUZZ_READER_H
