// mesh_data.h — a triangle mesh as it sits in a file: faces, optional positions, optional edge lengths, named per-vertex
// and per-edge scalar properties. The readers and writers (mesh_io.h) speak this; toTriangulation()/fromTriangulation()
// turn it into and out of an IntrinsicTriangulation. Positions are only ever used to compute edge lengths.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

struct EdgeRecord {
  int v0 = 0, v1 = 0;
  double length = 0;
};

struct MeshData {
  std::string source;  // file name (or description) used in error messages
  int nVertices = 0;
  std::vector<std::array<int, 3>> faces;  // triangles, 0-based
  // Optional: for each face corner k, the index into `edges` of edge (k, k+1). Present when the mesh is a Δ-complex
  // with multi-edges or self-loops (PLY face property `edge_index`), so that gluing does not use endpoint pairs.
  std::vector<std::array<int, 3>> cornerEdges;
  std::vector<Eigen::Vector3d> positions;  // empty for a metric-only mesh
  std::vector<EdgeRecord> edges;           // empty unless the file carries an edge element with lengths
  Background background = Background::Euclidean;
  std::map<std::string, std::vector<double>> vertexProperties;  // e.g. "u", "v", "lambda", "curvature"
  std::map<std::string, std::vector<double>> edgeProperties;    // parallel to `edges`
  std::vector<std::string> comments;                            // free-text header comments (not "geometry ...")
  int polygonsTriangulated = 0;    // polygons with more than three corners that the reader fan-triangulated
  int stripTriangles = 0;          // triangles read from PLY `element tristrips`
  int stripDegenerateSkipped = 0;  // strip triangles that repeat a vertex (strip joins), skipped
};

struct ConversionReport {
  BuildReport build;
  int unreferencedVerticesRemoved = 0;
  bool lengthsFromPositions = false;
  int polygonsTriangulated = 0, stripTriangles = 0;  // copied from MeshData: what the reader triangulated
  // Index of each input vertex in the triangulation, kInvalid for a removed (unreferenced) vertex; use it to carry
  // per-vertex properties and positions along.
  std::vector<int> vertexMap;
};

// Builds the triangulation: connectivity (validated), then edge lengths from `edges` when present (every mesh edge must
// be listed, with a finite positive length), otherwise from `positions` (finite coordinates required). Vertices used by
// no face are removed (counted in the report, with the index map). Lengths are validated against the triangle
// inequality of data.background. Throws InputError naming data.source and the element.
IntrinsicTriangulation toTriangulation(const MeshData& data, ConversionReport* report = nullptr);

// The inverse: faces, edges with lengths (and `edge_index` corner ids when the connectivity has multi-edges or
// self-loops), background; positions and properties are left for the caller to attach.
MeshData fromTriangulation(const IntrinsicTriangulation& tri);

}  // namespace conformesh::intrinsic
