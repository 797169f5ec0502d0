// vtk_writer.cpp — legacy ASCII VTK POLYDATA writer (vtk_writer.h).
#include "conformesh/intrinsic/io/vtk_writer.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"

namespace conformesh::intrinsic {

void writeVtk(const VtkMesh& mesh, const std::string& path) {
  const size_t n = mesh.points.size();
  for (const auto& [name, values] : mesh.pointFields) {
    if (values.size() != n)
      throw InputError(describeAt(path, "field '" + name + "' has " + std::to_string(values.size()) +
                                            " values, expected one per point (" + std::to_string(n) + ")"));
    if (name.find_first_of(" \t\n") != std::string::npos)
      throw InputError(describeAt(path, "field name '" + name + "' contains white space"));
  }
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int v : mesh.triangles[f])
      if (v < 0 || static_cast<size_t>(v) >= n)
        throw InputError(describeAt(path, "triangle " + std::to_string(f) + " refers to point " + std::to_string(v) +
                                              " of " + std::to_string(n)));
  {
    std::ostringstream out;
    char buf[96];
    out << "# vtk DataFile Version 3.0\n" << mesh.title << "\nASCII\nDATASET POLYDATA\nPOINTS " << n << " double\n";
    for (const auto& p : mesh.points) {
      std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
      out << buf;
    }
    out << "POLYGONS " << mesh.triangles.size() << " " << 4 * mesh.triangles.size() << "\n";
    for (const auto& t : mesh.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    if (!mesh.pointFields.empty()) {
      out << "POINT_DATA " << n << "\n";
      for (const auto& [name, values] : mesh.pointFields) {
        out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
        for (double x : values) {
          // ParaView reads "nan"; infinities are written as nan too, which it shows as missing.
          if (std::isfinite(x)) std::snprintf(buf, sizeof buf, "%.17g\n", x);
          else std::snprintf(buf, sizeof buf, "nan\n");
          out << buf;
        }
      }
    }
    writeFileAtomically(path, out.str());
  }
}

}  // namespace conformesh::intrinsic
