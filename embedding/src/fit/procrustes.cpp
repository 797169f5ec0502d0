// procrustes.cpp — Kabsch alignment with reflection handling (see procrustes.h).
#include "conformesh/embedding/fit/procrustes.h"

#include <cmath>
#include <string>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

namespace {

void checkPoints(const std::vector<Eigen::Vector3d>& pts, const char* which) {
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!pts[i].allFinite())
      throw InputError(std::string("procrustes: point ") + std::to_string(i) + " of the '" + which +
                       "' set is not finite");
}

}  // namespace

ProcrustesResult alignRigid(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
                            const ProcrustesOptions& options) {
  if (from.size() != to.size())
    throw InputError("procrustes: the point sets differ in size (" + std::to_string(from.size()) + " vs " +
                     std::to_string(to.size()) + ")");
  if (from.size() < 3)
    throw InputError("procrustes: need at least 3 corresponding points, found " + std::to_string(from.size()));
  checkPoints(from, "from");
  checkPoints(to, "to");

  const double n = static_cast<double>(from.size());
  Eigen::Vector3d cp = Eigen::Vector3d::Zero(), cq = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    cp += from[i];
    cq += to[i];
  }
  cp /= n;
  cq /= n;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();  // Σ (q − q̄)(p − p̄)ᵀ
  for (std::size_t i = 0; i < from.size(); ++i) cov += (to[i] - cq) * (from[i] - cp).transpose();

  // cov = U Σ Vᵀ; the best orthogonal map is U Vᵀ. With D = diag(1, 1, det(U Vᵀ)) it is the best rotation (Umeyama).
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d U = svd.matrixU(), V = svd.matrixV();
  const double d = (U * V.transpose()).determinant() > 0 ? 1.0 : -1.0;
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  if (!options.allowReflection) D(2, 2) = d;

  ProcrustesResult r;
  r.rotation = U * D * V.transpose();
  r.reflected = r.rotation.determinant() < 0;
  r.translation = cq - r.rotation * cp;
  double sum2 = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double e = (r.rotation * from[i] + r.translation - to[i]).norm();
    sum2 += e * e;
    r.maxError = std::max(r.maxError, e);
  }
  r.rmsError = std::sqrt(sum2 / n);
  return r;
}

std::vector<Eigen::Vector3d> applyRigid(const ProcrustesResult& motion, const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(motion.rotation * p + motion.translation);
  return out;
}

}  // namespace conformesh::embedding
