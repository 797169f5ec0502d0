// vtu_writer.h — VTK XML UnstructuredGrid (.vtu) output for ParaView, beside the legacy writer (vtk_writer.h): points,
// triangles (connectivity, offsets, cell types), every named per-point field, and the chart coordinates.
//
// Data arrays are inline base64 binary (format="binary", header_type="UInt64", no compression): the values read back
// bit for bit, NaN and infinities included (VTK's ASCII XML parser does not read "nan"), at about 11 characters per
// double against 17–24 for ASCII. docs/formats.md#vtu has the layout.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/io/vtk_writer.h"

namespace conformesh::intrinsic {

// Writes `mesh` (points, triangles, pointFields: one Float64 array each, named as in the map) and, when `chart` is not
// empty, the per-point chart coordinates (u, v) as the two-component Float64 array "chart" marked as the point data's
// TCoords. Cells are VTK_TRIANGLE (type 5); connectivity and offsets are Int64. The file is written to a temporary
// name and renamed. Throws InputError naming the path and the element for a field or chart of the wrong size, an empty
// field name, a triangle index out of range, and I/O failures.
void writeVtu(const VtkMesh& mesh, const std::string& path, const std::vector<Eigen::Vector2d>& chart = {});

}  // namespace conformesh::intrinsic
