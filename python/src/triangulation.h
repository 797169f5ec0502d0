// triangulation.h — the Python Triangulation: an IntrinsicTriangulation with what a file or a pipeline attached to
// it (positions, per-vertex fields) and how it was built (for summary()).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "bind_util.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::python {

struct Triangulation {
  intrinsic::IntrinsicTriangulation tri;
  std::vector<Eigen::Vector3d> positions;                   // per vertex, or empty
  std::map<std::string, std::vector<double>> fields;        // per-vertex fields
  std::string source;                                       // for messages and the reports' "input"
  intrinsic::ConversionReport reading;                      // what reading it did (reoriented faces, ...); no vertexMap
};
using TriangulationPtr = std::shared_ptr<Triangulation>;

// A file's content (or a pipeline's MeshData) as a Triangulation: validated by toTriangulation, positions and vertex
// properties carried along the vertex map.
TriangulationPtr fromMeshData(const intrinsic::MeshData& data);
TriangulationPtr fromIntrinsic(intrinsic::IntrinsicTriangulation tri, std::string source);
// The MeshData the writers take: faces, edges with lengths, positions and fields when present.
intrinsic::MeshData toMeshData(const Triangulation& t);

void bindTriangulation(py::module_& m);

}  // namespace conformesh::python
