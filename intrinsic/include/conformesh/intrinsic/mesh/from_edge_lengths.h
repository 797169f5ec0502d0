// from_edge_lengths.h — the library's entry point for a triangulation known by faces and edge lengths only (the input
// of geometry-central's `EdgeLengthGeometry`, of a numerical-relativity horizon finder's triangulated surface, ...).
//
// `fromEdgeLengths(faces, lengths)` builds an IntrinsicTriangulation with the same validation as the mesh readers
// (mesh_data.h's toTriangulation, which it calls): a manifold (or manifold-with-boundary) connectivity, finite positive
// lengths, the strict triangle inequality in every face, and — what only this entry point can get wrong — the two
// faces of an edge giving it the same length. Every error is an InputError naming options.source, the face, corner and
// vertices. Touches nothing else; no positions are ever involved.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::intrinsic {

struct FromEdgeLengthsOptions {
  Background background = Background::Euclidean;  // the geometry each face's lengths are meant in
  // Two faces' lengths for one edge agree when |a − b| ≤ relativeTolerance · max(a, b); the edge then gets (a + b)/2.
  // 0 demands bit-equal lengths. The default allows the last-bit differences of |p − q| computed in either order.
  double relativeTolerance = 1e-12;
  std::string source = "edge lengths";  // names the input in error messages
  // Returns "" when usable, otherwise what is wrong (expected vs found).
  std::string validate() const;
};

// faces[f] = {a, b, c} (0-based vertex indices, counter-clockwise as seen from the surface's chosen side; vertices are
// 0 … max index, and indices no face uses are dropped — see report->vertexMap). lengths[f][k] is the length of the
// side from faces[f][k] to faces[f][(k + 1) % 3], in the background's units. Edges are identified by their endpoint
// pairs, as in OBJ/OFF/PLY files without `edge_index` (a Δ-complex with multi-edges needs MeshData::cornerEdges and
// toTriangulation). Returns the triangulation (edge lengths per edge of tri.mesh); `report` (optional) receives the
// vertex map and HalfedgeMesh's build report. Throws InputError for invalid options, sizes that differ, an empty or
// negative index, a non-finite or non-positive length (naming face f, corner k), two faces disagreeing on an edge
// (naming both faces, the vertices and both lengths), non-manifold connectivity and triangle-inequality violations.
IntrinsicTriangulation fromEdgeLengths(const std::vector<std::array<int, 3>>& faces,
                                       const std::vector<std::array<double, 3>>& lengths,
                                       const FromEdgeLengthsOptions& options = {}, ConversionReport* report = nullptr);

}  // namespace conformesh::intrinsic
