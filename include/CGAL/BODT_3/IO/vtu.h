// Copyright (c) 2026 The CGAL BODT_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_BODT_3_IO_VTU_H
#define CGAL_BODT_3_IO_VTU_H

#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/dihedral_angles.h>
#include <CGAL/BODT_3/IO/write_atomically.h>

#include <cstdio>
#include <ostream>
#include <string>

namespace CGAL {
namespace BODT_3 {
namespace IO {

/// Writes `mesh` as an ASCII VTK XML UnstructuredGrid (`.vtu`) for ParaView: the
/// points (Float64, 17 significant digits), every tetrahedron (VTK type 10, label 0
/// ones included), and per tetrahedron the cell arrays "subdomain" (its label) and
/// "min_dihedral_angle" (degrees), so that bad elements can be found by thresholding.
inline void write_vtu(std::ostream& out, const Tet_mesh& mesh)
{
  char buf[96];
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << mesh.tets.size()
      << "\">\n"
         "      <Points>\n"
         "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : mesh.points)
  {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    out << buf;
  }
  out << "        </DataArray>\n"
         "      </Points>\n"
         "      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const auto& t : mesh.tets)
    out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < mesh.tets.size(); ++i)
    out << 4 * (i + 1) << '\n';
  out << "        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < mesh.tets.size(); ++i)
    out << "10\n";
  out << "        </DataArray>\n"
         "      </Cells>\n"
         "      <CellData Scalars=\"subdomain\">\n"
         "        <DataArray type=\"Int32\" Name=\"subdomain\" format=\"ascii\">\n";
  for(int label : mesh.tet_labels)
    out << label << '\n';
  out << "        </DataArray>\n"
         "        <DataArray type=\"Float64\" Name=\"min_dihedral_angle\" format=\"ascii\">\n";
  for(const auto& t : mesh.tets)
  {
    const double a = min_max_dihedral_angle(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]],
                                            mesh.points[t[3]]).first;
    std::snprintf(buf, sizeof buf, "%.17g\n", a);
    out << buf;
  }
  out << "        </DataArray>\n"
         "      </CellData>\n"
         "    </Piece>\n"
         "  </UnstructuredGrid>\n"
         "</VTKFile>\n";
}

inline void write_vtu(const std::string& file, const Tet_mesh& mesh)
{
  write_atomically(file, [&](std::ostream& out) { write_vtu(out, mesh); });
}

} // namespace IO
} // namespace BODT_3
} // namespace CGAL

#endif // CGAL_BODT_3_IO_VTU_H
