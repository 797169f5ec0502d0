// Tests for spatial_metric.h: the analytic 3-metrics against closed forms evaluated independently (on the axis and in
// the equatorial plane, where Kerr–Schild reduces to one-line expressions), the Kerr–Schild structure (l null and
// unit in the flat metric, det γ = 1 + 2H, r on its spheroid), and the analytic derivatives against central
// differences, whose error must fall at order 2 (log–log fit over four steps).
#include <catch2/catch.hpp>

#include <cmath>

#include <Eigen/LU>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/spatial_metric_registry.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/metric/spatial_metric.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

TEST_CASE("spatial metric: Kerr-Schild reduces to its closed forms on the axis and for a = 0") {
  const double M = 1.3, a = 0.9;
  const KerrSchildMetric ks(M, a, Eigen::Vector3d::Zero());
  // On the axis x = y = 0: r = |z|, H = M r/(r² + a²), l = (0, 0, 1), so γ_zz = 1 + 2Mr/(r² + a²), others δ.
  const double z = 2.7;
  const Eigen::Matrix3d g = ks.gamma({0, 0, z});
  CHECK(ks.radius({0, 0, z}) == Approx(z).epsilon(1e-15));
  CHECK(g(2, 2) == Approx(1 + 2 * M * z / (z * z + a * a)).epsilon(1e-14));
  CHECK(g(0, 0) == Approx(1).epsilon(1e-15));
  CHECK(std::abs(g(0, 2)) < 1e-15);
  // a = 0: Schwarzschild in Kerr–Schild form, γ_ij = δ_ij + (2M/r) n_i n_j.
  const KerrSchildMetric s(M, 0, Eigen::Vector3d::Zero());
  const Eigen::Vector3d x(1.1, -0.7, 2.3);
  const Eigen::Vector3d n = x.normalized();
  CHECK((s.gamma(x) - (Eigen::Matrix3d::Identity() + 2 * M / x.norm() * n * n.transpose())).norm() < 1e-14);
}

TEST_CASE("spatial metric: Kerr-Schild structure off the axis, and a translated centre") {
  const double M = 1, a = 0.95;
  const Eigen::Vector3d c(0.3, -0.2, 0.5), y(1.2, 0.8, -0.9);
  const KerrSchildMetric ks(M, a, c), ks0(M, a, Eigen::Vector3d::Zero());
  const double r = ks.radius(c + y);
  // r lies on its spheroid (x² + y²)/(r² + a²) + z²/r² = 1.
  CHECK((y.x() * y.x() + y.y() * y.y()) / (r * r + a * a) + y.z() * y.z() / (r * r) == Approx(1).epsilon(1e-14));
  // γ − δ = 2H l lᵀ has rank one; with |l| = 1 (l is null in the spacetime, unit in the flat metric),
  // det γ = 1 + 2H and (γ − δ) l = 2H l.
  const double H = M * r * r * r / (r * r * r * r + a * a * y.z() * y.z());
  const Eigen::Matrix3d g = ks.gamma(c + y);
  CHECK(g.determinant() == Approx(1 + 2 * H).epsilon(1e-14));
  const Eigen::Vector3d l((r * y.x() + a * y.y()) / (r * r + a * a), (r * y.y() - a * y.x()) / (r * r + a * a),
                          y.z() / r);
  CHECK(l.norm() == Approx(1).epsilon(1e-14));
  CHECK(((g - Eigen::Matrix3d::Identity()) * l - 2 * H * l).norm() < 1e-14);
  // Translation: γ_c(c + y) = γ_0(y).
  CHECK((g - ks0.gamma(y)).norm() < 1e-14);
  CHECK(ks.horizonRadius() == Approx(1 + std::sqrt(1 - a * a)).epsilon(1e-15));
}

TEST_CASE("spatial metric: isotropic Schwarzschild and flat") {
  const IsotropicSchwarzschildMetric s(1, Eigen::Vector3d(0, 0, 1));
  // ρ = 1, M = 1: ψ = 3/2, ψ⁴ = 81/16.
  CHECK((s.gamma({0, 1, 1}) - 81.0 / 16 * Eigen::Matrix3d::Identity()).norm() < 1e-14);
  CHECK_THROWS_WITH(s.gamma({0, 0, 1}), Catch::Contains("puncture"));
  const FlatSpatialMetric f;
  CHECK(f.gamma({4, 5, 6}) == Eigen::Matrix3d::Identity());
}

TEST_CASE("spatial metric: analytic derivatives agree with central differences at order 2") {
  std::vector<std::unique_ptr<SpatialMetric>> metrics;
  metrics.push_back(makeSpatialMetric("kerr-schild", {{"M", 1}, {"a", 0.8}, {"cx", 0.1}}));
  metrics.push_back(makeSpatialMetric("kerr-schild", {{"M", 1}, {"a", 0.95}}));
  metrics.push_back(makeSpatialMetric("schwarzschild-isotropic", {{"M", 1}, {"cz", -0.3}}));
  // Points near the horizons (r ≈ 1.3–2), where the pull-back evaluates γ, off every symmetry plane.
  const std::vector<Eigen::Vector3d> points = {{1.1, 0.6, -0.8}, {0.3, -1.4, 0.9}, {-0.9, 0.2, 1.5}};
  for (const auto& m : metrics)
    for (const Eigen::Vector3d& x : points) {
      INFO(m->description() << " at " << x.transpose());
      const SpatialMetricJet j = m->jet(x);
      CHECK((j.g - m->gamma(x)).norm() < 1e-15);
      // Steps 0.04 → 0.005: truncation h²/6·|γ'''| ≈ 1e-4 … 1e-6 dominates round-off ε/h ≈ 1e-14 by far.
      std::vector<double> hs, errors;
      for (double h : {0.04, 0.02, 0.01, 0.005}) {
        double e = 0;
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d dx = h * Eigen::Vector3d::Unit(k);
          e = std::max(e, ((m->gamma(x + dx) - m->gamma(x - dx)) / (2 * h) - j.d[k]).cwiseAbs().maxCoeff());
        }
        hs.push_back(h), errors.push_back(e);
      }
      INFO("errors " << errors[0] << " " << errors[3]);
      CHECK(fitLogLogSlope(hs, errors) == Approx(2).margin(0.1));
    }
}

TEST_CASE("spatial metric: the registry names what is wrong") {
  CHECK_THROWS_WITH(makeSpatialMetric("kerr", {}), Catch::Contains("unknown spatial metric 'kerr'"));
  CHECK_THROWS_WITH(makeSpatialMetric("kerr-schild", {{"q", 1}}), Catch::Contains("unknown parameter 'q'"));
  CHECK_THROWS_WITH(makeSpatialMetric("kerr-schild", {{"a", 1.2}}), Catch::Contains("|a| <= M"));
  CHECK_THROWS_WITH(makeSpatialMetric("schwarzschild-isotropic", {{"M", -1}}), Catch::Contains("> 0"));
  CHECK(makeSpatialMetric("kerr-schild", {{"a", 0.5}})->description() == "kerr-schild M=1 a=0.5");
  CHECK_THROWS_WITH(KerrSchildMetric(1, 0.5, Eigen::Vector3d::Zero()).gamma({0.5, 0, 0}),
                    Catch::Contains("ring singularity"));
}
