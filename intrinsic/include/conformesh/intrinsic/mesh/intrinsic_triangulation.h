// intrinsic_triangulation.h — a triangulated surface known by connectivity and edge lengths only, with the background
// geometry (0, +1, −1 curvature) in which each triangle's lengths are meant.
//
// This is the object every stage of conformesh passes along: T0 (discretized metric), T0* (uniformized), T1* (refined)
// and T1 (pulled back). Geometry queries are free functions over it; they read lengths, never positions.
// To build one from faces and edge lengths, call fromEdgeLengths (from_edge_lengths.h); from a file, readMesh and
// toTriangulation (mesh_io.h, mesh_data.h).
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/halfedge_mesh.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::intrinsic {

struct IntrinsicTriangulation {
  HalfedgeMesh mesh;
  std::vector<double> edgeLengths;  // per edge
  Background background = Background::Euclidean;

  double length(int h) const { return edgeLengths[mesh.edge(h)]; }
};

// Throws InputError naming `source`, the first offending face and its three lengths if any face's lengths are not
// finite, not positive, or violate the (strict) triangle inequality of the background; also when edgeLengths has the
// wrong size.
void validateLengths(const IntrinsicTriangulation& tri, const std::string& source = "");

// === per-element geometry
// Angle at tail(h) in face(h): between h and prev(h).
double cornerAngle(const IntrinsicTriangulation& tri, int h);
double faceArea(const IntrinsicTriangulation& tri, int f);
double faceCircumradius(const IntrinsicTriangulation& tri, int f);
// cot of the angle opposite halfedge h in its face.
double cotanOpposite(const IntrinsicTriangulation& tri, int h);
// ½ Σ cot of the angles opposite e (one term on the boundary); the Euclidean cotan-Laplace weight.
double cotanWeight(const IntrinsicTriangulation& tri, int e);

// === whole-mesh arrays
std::vector<double> allCornerAngles(const IntrinsicTriangulation& tri);  // indexed by halfedge
double totalArea(const IntrinsicTriangulation& tri);

// === Delaunay
// Local Delaunay test of interior edge e in the background geometry: with α, β the angles opposite e and ρ the sum of
// the four other angles of its two triangles, e is Delaunay iff α + β ≤ ρ (Bobenko–Springborn; for the Euclidean plane
// this is α + β ≤ π, i.e. cot α + cot β ≥ 0). Returns ρ − (α + β) scaled by ½: positive for strictly Delaunay, zero
// for cocircular, negative for non-Delaunay. Boundary edges return +infinity.
double delaunayMargin(const IntrinsicTriangulation& tri, int e);

}  // namespace conformesh::intrinsic
