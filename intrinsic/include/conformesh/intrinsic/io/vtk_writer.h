// vtk_writer.h — legacy VTK (POLYDATA, ASCII) output for ParaView: triangles, points, and named per-vertex scalar fields.
//
// Intrinsic meshes have no positions of their own; callers pass the embedding where one is known and otherwise a
// picture of the surface (e.g. the chart's reference sphere), which the fields then colour.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace conformesh::intrinsic {

struct VtkMesh {
  std::string title = "conformesh";
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::map<std::string, std::vector<double>> pointFields;  // one value per point each
};

// Writes to a temporary file and renames it, so a failed write never clobbers an existing file. Throws InputError
// naming the path and the field for a field of the wrong size, and for I/O failures.
void writeVtk(const VtkMesh& mesh, const std::string& path);

}  // namespace conformesh::intrinsic
