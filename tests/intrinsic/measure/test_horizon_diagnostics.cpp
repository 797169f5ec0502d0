// Tests for horizon_diagnostics.h: Kerr's circumference ratio against its closed-form endpoints, its inverse, and the
// diagnostics of Kerr horizons from their intrinsic metric alone — Smarr's metric (kerr-newman family) and the
// Kerr–Schild coordinate spheroid fitted as a Strahlkörper — against A = 8πMr₊, C_eq = 4πM and the true spin.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/metric_families.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

TEST_CASE("horizon diagnostics: Kerr's circumference ratio and its inverse") {
  CHECK(kerrCircumferenceRatio(0) == Approx(1).epsilon(1e-15));
  // χ = 1: r₊ = M, m = 1/2, ratio = √2 E(1/2)/π with E(1/2) = 1.3506438810476755 (A&S table 17.1, k² = 1/2).
  CHECK(kerrCircumferenceRatio(1) == Approx(std::sqrt(2.0) * 1.3506438810476755 / M_PI).epsilon(1e-14));
  for (double chi : {0.0, 0.1, 0.5, 0.9, 0.999, 1.0})
    CHECK(spinFromCircumferenceRatio(kerrCircumferenceRatio(chi)) == Approx(chi).margin(1e-7));
  CHECK(std::isnan(spinFromCircumferenceRatio(1.1)));
  CHECK(std::isnan(spinFromCircumferenceRatio(0.5)));
}

TEST_CASE("horizon diagnostics: Kerr horizons give area, irreducible mass, circumferences and spin") {
  for (double chi : {0.3, 0.6, 0.9}) {
    const double rp = 1 + std::sqrt(1 - chi * chi);
    const KerrNewmanMetric smarr(1, chi, 0);
    // The Kerr–Schild horizon spheroid, fitted at l_max = 16, in the Kerr–Schild γ about a translated centre.
    const Eigen::Vector3d c(0.4, 0.1, -0.6);
    const double A2 = rp * rp + chi * chi, C2 = rp * rp;
    const Strahlkorper shape = fitStrahlkorper(
        [&](double t, double) { return 1 / std::sqrt(std::pow(std::sin(t), 2) / A2 + std::pow(std::cos(t), 2) / C2); },
        16, c);
    const HorizonSurfaceMetric ks(shape, std::make_shared<KerrSchildMetric>(1, chi, c));
    for (const SmoothMetric* m : {static_cast<const SmoothMetric*>(&smarr), static_cast<const SmoothMetric*>(&ks)}) {
      INFO(m->description());
      const HorizonDiagnostics d = horizonDiagnostics(*m);
      CHECK(d.area == Approx(8 * M_PI * rp).epsilon(1e-8));
      CHECK(d.irreducibleMass == Approx(std::sqrt(rp / 2)).epsilon(1e-8));
      CHECK(d.equatorialCircumference == Approx(4 * M_PI).epsilon(1e-8));
      CHECK(d.minPolarCircumference == Approx(d.polarCircumference).epsilon(1e-8));  // axisymmetric
      // The bar is 1e-3; the trapezoidal rule is spectral, so the estimate is far closer.
      CHECK(std::abs(d.spin - chi) < 1e-6);
    }
  }
}

TEST_CASE("horizon diagnostics: bad input is named") {
  const TorusMetric torus(1, 0.4);
  CHECK_THROWS_WITH(horizonDiagnostics(torus), Catch::Contains("sphere chart"));
  HorizonDiagnosticsOptions o;
  o.curvePoints = 3;
  CHECK_THROWS_WITH(horizonDiagnostics(KerrNewmanMetric(1, 0.5, 0), o), Catch::Contains("curvePoints"));
}
