// test_procrustes.cpp — Kabsch alignment: a known rigid motion is recovered to round-off, mirror images are handled
// as documented, and bad input names what is wrong.
#include <cmath>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "conformesh/embedding/fit/procrustes.h"
#include "conformesh/intrinsic/errors.h"

using namespace conformesh;
using namespace conformesh::embedding;

namespace {

std::vector<Eigen::Vector3d> cloud(int n) {
  // A deterministic, non-degenerate point cloud (points on a twisted curve, not coplanar).
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    const double t = 0.37 * i;
    p.emplace_back(std::cos(t) + 0.1 * i, std::sin(2 * t), 0.05 * i * i - std::cos(3 * t));
  }
  return p;
}

}  // namespace

TEST_CASE("a known rigid motion is recovered to round-off") {
  const auto p = cloud(40);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.234, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(2.5, -1.0, 0.75);
  std::vector<Eigen::Vector3d> q;
  for (const auto& x : p) q.push_back(R * x + t);
  const auto r = alignRigid(p, q);
  CHECK_FALSE(r.reflected);
  CHECK((r.rotation - R).norm() < 1e-13);
  CHECK((r.translation - t).norm() < 1e-13);
  CHECK(r.rmsError < 1e-13);
  CHECK(r.maxError < 1e-13);
  const auto moved = applyRigid(r, p);
  for (std::size_t i = 0; i < p.size(); ++i) CHECK((moved[i] - q[i]).norm() < 1e-13);
}

TEST_CASE("a mirror image aligns exactly only when reflections are allowed") {
  const auto p = cloud(25);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<Eigen::Vector3d> q;
  for (const auto& x : p) q.push_back(R * Eigen::Vector3d(x.x(), x.y(), -x.z()));
  const auto withMirror = alignRigid(p, q);
  CHECK(withMirror.reflected);
  CHECK(withMirror.rotation.determinant() == Approx(-1.0).margin(1e-12));
  CHECK(withMirror.rmsError < 1e-13);
  ProcrustesOptions proper;
  proper.allowReflection = false;
  const auto rotationOnly = alignRigid(p, q, proper);
  CHECK_FALSE(rotationOnly.reflected);
  CHECK(rotationOnly.rotation.determinant() == Approx(1.0).margin(1e-12));
  CHECK(rotationOnly.rmsError > 0.1);  // a non-planar cloud is not congruent to its mirror image
}

TEST_CASE("noise: the RMS error is the least-squares optimum, below that of the true motion") {
  auto p = cloud(60);
  std::vector<Eigen::Vector3d> q;
  for (std::size_t i = 0; i < p.size(); ++i)
    q.push_back(p[i] + 1e-3 * Eigen::Vector3d(std::sin(7.0 * i), std::cos(5.0 * i), std::sin(3.0 * i + 1)));
  const auto r = alignRigid(p, q);
  double identityRms = 0;
  for (std::size_t i = 0; i < p.size(); ++i) identityRms += (p[i] - q[i]).squaredNorm();
  identityRms = std::sqrt(identityRms / p.size());
  CHECK(r.rmsError <= identityRms);
  CHECK(r.rmsError > 0.5 * identityRms);  // the noise is not a rigid motion
}

TEST_CASE("bad input is reported") {
  const auto p = cloud(5);
  CHECK_THROWS_AS(alignRigid(p, cloud(4)), InputError);
  CHECK_THROWS_WITH(alignRigid(p, cloud(4)), Catch::Contains("5 vs 4"));
  CHECK_THROWS_WITH(alignRigid(cloud(2), cloud(2)), Catch::Contains("at least 3"));
  auto bad = p;
  bad[3].y() = NAN;
  CHECK_THROWS_WITH(alignRigid(p, bad), Catch::Contains("point 3") && Catch::Contains("not finite"));
}
