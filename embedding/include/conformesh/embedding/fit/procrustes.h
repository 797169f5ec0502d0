// procrustes.h — rigid alignment of two point sets with known correspondence (Kabsch 1976, with Umeyama's sign
// correction): the rotation R and translation t minimizing Σ |R p_i + t − q_i|², optionally allowing a reflection
// (edge lengths cannot tell a surface from its mirror image). Used to compare a fitted embedding with the true
// surface: the RMS and largest distance after alignment are the "Procrustes error".
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
