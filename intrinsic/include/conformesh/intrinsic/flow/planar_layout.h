// planar_layout.h — laying out a flat (Euclidean) intrinsic triangulation in the plane by breadth-first unfolding,
// carrying edge directions by rotation (used for circle domains, the punctured sphere and boundary flattening).
// Touches nothing but its arguments; depends on the mesh layer only. docs/ricci_flow.md §3.1 ("Map back") and
// "Uniformization targets and the genus-0 puncture" say why directions are rotated, not recomputed.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// Lays out a flat triangulation of a topological disk or planar domain: one point per vertex (plane coordinates, in
// the units of `tri`'s lengths), the first unskipped face's first edge on the positive x-axis from the origin; a piece
// of unskipped faces not reached from earlier ones is unfolded from its lowest-numbered face. Faces with skipFaces[f]
// != 0 are not laid out (empty: none); vertices only in skipped faces stay at the origin. Throws InputError when `tri`
// is not Euclidean, and ConvergenceError when a vertex reached twice lands more than `mismatch` × (mean edge length)
// away from itself — i.e. the metric is not flat or has holonomy.
std::vector<Eigen::Vector2d> layoutFlat(const IntrinsicTriangulation& tri, double mismatch = 1e-6,
                                        const std::vector<char>& skipFaces = {});

// A boundary loop of a laid-out circle domain against its circle: the circle through three spread vertices of `loop`
// (indices into `z`: its first, one a third and one two thirds along) and the largest relative deviation
// |‖z_v − centre‖ − radius| / radius of the loop's vertices from it. Used by uniformize and by the output verification.
struct LoopCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0, deviation = 0;
};
LoopCircle fitLoopCircle(const std::vector<Eigen::Vector2d>& z, const std::vector<int>& loop);

}  // namespace conformesh::intrinsic
