// intrinsic_flips.h — isometric edge flips of an intrinsic triangulation and Lawson flipping to the intrinsic Delaunay
// triangulation of its metric (Bobenko–Springborn 2007, in each background geometry).
#pragma once

#include <cstdint>
#include <functional>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// Flips interior edge e if its quadrilateral is strictly convex at both ends of e (otherwise the flip would not be an
// isometry of the same surface) and gives it the length of the other diagonal, computed in the background geometry.
// Returns false and changes nothing when the edge is on the boundary, both sides are one face, or the quad is not
// convex.
bool flipEdge(IntrinsicTriangulation& tri, int e);

struct DelaunayOptions {
  // An edge is flipped when its delaunayMargin is below −tolerance (radians). 1e-12 sits a few hundred ulps above the
  // round-off of a margin built from six angles, so cocircular configurations are left alone instead of flipping back
  // and forth; see docs/theory.md.
  double tolerance = 1e-12;
  // Safety cap on flips, as a multiple of the edge count; Lawson flipping terminates on every valid input in finitely
  // many flips, so hitting the cap means the input was invalid or the tolerance too small, and ConvergenceError is
  // thrown.
  std::int64_t maxFlipsPerEdge = 1000;
  // Called after each successful flip with the edge index (e.g. to update correspondences); may be empty.
  std::function<void(int)> onFlip;
};

struct DelaunayReport {
  std::int64_t flips = 0;
  int nonDelaunayBefore = 0;
};

// Flips to the intrinsic Delaunay triangulation: on return every interior edge has delaunayMargin ≥ −tolerance.
DelaunayReport makeDelaunay(IntrinsicTriangulation& tri, const DelaunayOptions& options = {});

// Number of interior edges with delaunayMargin < −tolerance.
int countNonDelaunayEdges(const IntrinsicTriangulation& tri, double tolerance = DelaunayOptions{}.tolerance);

}  // namespace conformesh::intrinsic
