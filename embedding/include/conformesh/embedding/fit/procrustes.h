// procrustes.h — rigid alignment of two point sets with known correspondence (orthogonal Procrustes / Kabsch): the
// rotation R and translation t minimizing Σ |R p_i + t − q_i|², optionally allowing a reflection.
//
// A fitted embedding (isometric_embedding.h) is determined by the edge lengths only up to a rigid motion — and up to a
// mirror image, since lengths cannot tell a surface from its reflection. Comparing it with the true surface therefore
// means aligning first; the RMS and largest distance after alignment are the "Procrustes error".
//
// Method: Kabsch (1976), with the SVD of the 3×3 cross-covariance; the sign correction on the smallest singular
// direction keeps det R = +1 (Umeyama 1991) unless reflections are allowed, in which case the better of the two is
// taken.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace conformesh::embedding {

struct ProcrustesOptions {
  // Allow an improper orthogonal map (det = −1). The default is true because an isometric fit cannot distinguish a
  // surface from its mirror image; set false to demand a proper rotation.
  bool allowReflection = true;
};

struct ProcrustesResult {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // orthogonal; det −1 when `reflected`
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  bool reflected = false;
  double rmsError = 0;  // √(Σ |R p_i + t − q_i|² / n) after alignment
  double maxError = 0;  // max_i |R p_i + t − q_i|
};

// Aligns `from` onto `to` (same size, at least 3 points, finite). Throws InputError for sizes that differ, fewer than
// three points, or a non-finite coordinate (naming the point).
ProcrustesResult alignRigid(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                            const ProcrustesOptions& options = {});

// R p + t for every point.
std::vector<Eigen::Vector3d> applyRigid(const ProcrustesResult& motion, const std::vector<Eigen::Vector3d>& points);

}  // namespace conformesh::embedding
