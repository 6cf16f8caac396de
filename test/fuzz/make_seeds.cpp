// Writes the seed corpus of the reader harnesses: small meshes in every format and
// variant, from a generated grid and from a piece of each mesh given on the command
// line (scripts/fuzz.sh passes CGAL's Mesh_3-made sphere.mesh).
//
// usage: make_seeds OUTPUT_DIR [MESH...]
#include <CGAL/BODT_3/IO/mesh_io.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace IO = CGAL::BODT_3::IO;
using CGAL::BODT_3::Tet_mesh;
namespace fs = std::filesystem;

namespace {

// Two cubes of six tetrahedra each, labels 1 and 2, every entity a format may keep.
Tet_mesh grid()
{
  Tet_mesh m;
  const int n = 2;
  auto id = [&](int i, int j, int k) { return (k * 2 + j) * (n + 1) + i; };
  for(int k = 0; k < 2; ++k)
    for(int j = 0; j < 2; ++j)
      for(int i = 0; i <= n; ++i)
      {
        m.points.emplace_back(i + 0.1 * j / 3.0, j - 0.01 * k, k + 1e-3 * i);
        m.vertex_refs.push_back(i % 2);
      }
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(int i = 0; i < n; ++i)
    for(const auto& path : paths)
    {
      int c[3] = {i, 0, 0};
      std::array<int, 4> t;
      t[0] = id(c[0], c[1], c[2]);
      for(int s = 0; s < 3; ++s)
      {
        ++c[path[s]];
        t[s + 1] = id(c[0], c[1], c[2]);
      }
      if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) != CGAL::POSITIVE)
        std::swap(t[2], t[3]);
      m.tets.push_back(t);
      m.tet_labels.push_back(i + 1);
    }
  m.triangles = {{id(0, 0, 0), id(1, 0, 0), id(1, 1, 0)}, {id(0, 0, 0), id(1, 1, 0), id(0, 1, 0)}};
  m.triangle_labels = {5, 6};
  m.edges = {{id(0, 0, 0), id(1, 0, 0)}, {id(1, 0, 0), id(2, 0, 0)}};
  m.edge_labels = {3, 3};
  m.corners = {id(0, 0, 0), id(2, 1, 1)};
  m.required_vertices = {id(1, 0, 0)};
  m.ridges = {1};
  return m;
}

// The first `count` tetrahedra of `m`, with the vertices and triangles they use.
Tet_mesh piece(const Tet_mesh& m, std::size_t count)
{
  Tet_mesh p;
  std::map<int, int> index;
  auto vertex = [&](int v) {
    auto it = index.emplace(v, static_cast<int>(p.points.size()));
    if(it.second)
    {
      p.points.push_back(m.points[v]);
      p.vertex_refs.push_back(m.vertex_refs[v]);
    }
    return it.first->second;
  };
  for(std::size_t t = 0; t < m.tets.size() && t < count; ++t)
  {
    std::array<int, 4> c;
    for(int k = 0; k < 4; ++k) c[k] = vertex(m.tets[t][k]);
    p.tets.push_back(c);
    p.tet_labels.push_back(m.tet_labels[t]);
  }
  for(std::size_t f = 0; f < m.triangles.size(); ++f)
  {
    const auto& t = m.triangles[f];
    if(index.count(t[0]) && index.count(t[1]) && index.count(t[2]))
    {
      p.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
      p.triangle_labels.push_back(m.triangle_labels[f]);
    }
  }
  return p;
}

void write(const fs::path& file, const std::string& bytes)
{
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
}

void write_all(const fs::path& out, const std::string& name, const Tet_mesh& m)
{
  auto text = [&](auto&& writer) {
    std::ostringstream s;
    writer(s);
    return s.str();
  };
  for(int v = 1; v <= 4; ++v)
  {
    write(out / "medit" / (name + std::to_string(v) + ".mesh"), text([&](std::ostream& s) { IO::write_medit(s, m, v); }));
    write(out / "meshb" / (name + std::to_string(v) + ".meshb"), text([&](std::ostream& s) { IO::write_meshb(s, m, v); }));
  }
  for(int v : {22, 41})
    for(bool b : {false, true})
      write(out / "gmsh" / (name + std::to_string(v) + (b ? "b" : "") + ".msh"),
            text([&](std::ostream& s) { IO::write_gmsh(s, m, v, b); }));
  for(bool b : {false, true})
  {
    write(out / "vtu" / (name + (b ? "b" : "") + ".vtu"), text([&](std::ostream& s) { IO::write_vtu(s, m, b); }));
    for(int v : {42, 51})
      write(out / "vtk" / (name + std::to_string(v) + (b ? "b" : "") + ".vtk"),
            text([&](std::ostream& s) { IO::write_vtk(s, m, b, v); }));
  }
  std::ostringstream node, ele, face, edge;
  IO::internal::write(node, ele, face, edge, m);
  write(out / "tetgen" / (name + ".tetgen"), node.str() + "\n%%\n" + ele.str() + "\n%%\n" + face.str() + "\n%%\n" + edge.str());
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: make_seeds OUTPUT_DIR [MESH...]\n";
    return 2;
  }
  const fs::path out = argv[1];
  write_all(out, "grid", grid());
  for(int i = 2; i < argc; ++i)
  {
    std::ostringstream warnings;
    const Tet_mesh m = IO::read_mesh(argv[i], warnings);
    write_all(out, fs::path(argv[i]).stem().string() + "_piece", piece(m, 24));
  }
  return 0;
}
