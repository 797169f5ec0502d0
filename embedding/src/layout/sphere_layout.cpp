// sphere_layout.cpp — Möbius balancing on the unit sphere, rotation normalization, stereographic projection. See
// sphere_layout.h and docs/layout.md §5.
#include "conformesh/embedding/layout/sphere_layout.h"

#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::IntrinsicTriangulation;

std::vector<double> vertexAreas(const IntrinsicTriangulation& tri) {
  std::vector<double> w(tri.mesh.nVertices(), 0.0);
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    const double a = intrinsic::faceArea(tri, f) / 3;
    for (int k = 0; k < 3; ++k) w[tri.mesh.faceVertex(f, k)] += a;
  }
  return w;
}

namespace {

Eigen::Vector3d weightedCentroid(const std::vector<Eigen::Vector3d>& p, const std::vector<double>& w) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double total = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    c += w[i] * p[i];
    total += w[i];
  }
  return c / total;
}

}  // namespace

int balanceOnSphere(std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                    const BalanceOptions& options) {
  if (weights.size() != points.size())
    throw InputError("balanceOnSphere: " + std::to_string(weights.size()) + " weights for " +
                     std::to_string(points.size()) + " points");
  for (std::size_t i = 0; i < weights.size(); ++i)
    if (!(weights[i] >= 0))
      throw InputError("balanceOnSphere: weight of point " + std::to_string(i) + " is " + std::to_string(weights[i]) +
                       ", expected >= 0");
  for (int iter = 0; iter <= options.maxIterations; ++iter) {
    const Eigen::Vector3d centroid = weightedCentroid(points, weights);
    if (centroid.norm() <= options.tolerance) return iter;
    if (iter == options.maxIterations) {
      std::ostringstream s;
      s << "balanceOnSphere: centroid still at distance " << centroid.norm() << " from the origin after "
        << options.maxIterations << " Möbius steps (tolerance " << options.tolerance << ")";
      throw ConvergenceError(s.str());
    }
    const Eigen::Vector3d c = 0.75 * centroid;
    const double s = 1 - c.squaredNorm();
    for (auto& x : points) {
      x = s * (x - c) / (x - c).squaredNorm() - c;
      x.normalize();  // |φ_c(x)| = 1 exactly; renormalizing keeps round-off from accumulating off the sphere
    }
  }
  return options.maxIterations;
}

SphereLayout layoutSphere(const intrinsic::Uniformization& u, const std::vector<double>& weights,
                          const SphereLayoutOptions& options) {
  if (u.report.target != intrinsic::UniformizationTarget::Sphere)
    throw InputError("layoutSphere: expected a sphere uniformization (closed genus 0), found target " +
                     intrinsic::toString(u.report.target));
  const int n = static_cast<int>(u.positions.size());
  for (int v : {options.centreVertex, options.directionVertex})
    if (v < -1 || v >= n)
      throw InputError("layoutSphere: vertex " + std::to_string(v) + " out of range [0, " + std::to_string(n) + ")");
  SphereLayout s;
  s.points = u.positions;
  const std::vector<double> w = weights.empty() ? std::vector<double>(n, 1.0) : weights;
  s.balanceIterations = balanceOnSphere(s.points, w, options.balance);
  // Rotations commute with the balancing (they keep the centroid at 0).
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
  if (options.centreVertex >= 0)
    rot = Eigen::Quaterniond::FromTwoVectors(s.points[options.centreVertex], Eigen::Vector3d(0, 0, -1))
              .toRotationMatrix();
  if (options.directionVertex >= 0) {
    const Eigen::Vector3d d = rot * s.points[options.directionVertex];
    rot = Eigen::AngleAxisd(-std::atan2(d.y(), d.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix() * rot;
  }
  for (auto& p : s.points) p = rot * p;
  s.centroid = weightedCentroid(s.points, w);
  s.plane.reserve(n);
  // The north pole itself projects to infinity: reported as (+inf, +inf) rather than the NaN of 0/0. 1e-15 is a few ε
  // of the unit-length points, below which 1 − z carries no digits.
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const auto& p : s.points)
    s.plane.push_back(1 - p.z() < 1e-15 ? Eigen::Vector2d(inf, inf)
                                        : Eigen::Vector2d(p.x() / (1 - p.z()), p.y() / (1 - p.z())));
  return s;
}

}  // namespace conformesh::embedding
