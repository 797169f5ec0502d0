// robust_predicates.h — the sign of det[a b c] for three vectors of R³, exact for the doubles it is given: the
// orientation predicate of every combinatorial decision of the refinement in the models of background_model.h (planar
// orient2d for (x, y, 1), spherical / hyperbolic orientation for model vectors). A floating-point filter answers almost
// always; otherwise the determinant is recomputed exactly in Boost.Multiprecision integers. Pure functions, no state.
// docs/refinement.md §3.
#pragma once

#include <Eigen/Core>

namespace conformesh::refine {

// +1, 0 or −1: the exact sign of det[a b c] (columns a, b, c).
int orientationSign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The same, computed only exactly (for tests of the filter).
int orientationSignExact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace conformesh::refine
