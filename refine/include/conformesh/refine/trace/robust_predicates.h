// robust_predicates.h — the sign of det[a b c] for three vectors of R³, exact for the doubles it is given.
//
// Every combinatorial decision of the refinement (which edge a geodesic trace leaves a triangle through, whether the
// target lies inside a triangle) is the sign of such a determinant in the models of background_model.h: for (x, y, 1)
// vectors it is the planar orient2d predicate, for unit vectors and hyperboloid vectors the orientation of the
// spherical / hyperbolic triangle. A floating-point filter (Shewchuk-style error bound on the permanent) answers almost
// always; when it cannot certify the sign, the determinant is recomputed exactly in Boost.Multiprecision integers.
// Exactness is with respect to the coordinates as computed: the layout itself carries round-off, but every decision is
// consistent with one planar (projective) configuration, so a trace can never take two contradictory branches.
#pragma once

#include <Eigen/Core>

namespace conformesh::refine {

// +1, 0 or −1: the exact sign of det[a b c] (columns a, b, c).
int orientationSign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The same, computed only exactly (for tests of the filter).
int orientationSignExact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace conformesh::refine
