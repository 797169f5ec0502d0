// test_metric_families.cpp — each built-in family's curvature, area and total curvature against closed forms: Kerr
// horizon area 8πMr₊ and equatorial circumference 4πM at every spin, the sign change of K at the poles at a/M = √3/2;
// the ellipsoid's K and area against GeographicLib; the torus's positive and negative curvature; caps, hyperbolic
// disks, flat tori, graphs and Bézier patches; parameter errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include <GeographicLib/Ellipsoid.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {
// Pull-back of the embedding by fourth-order central differences (error ~ (h/l)^4 for features of size l, plus
// round-off eps/h ~ 1e-12): checks g against position().
double embeddingMismatch(const SmoothMetric& m, double u, double v) {
  const double h = 1e-4;
  auto d = [&](double du, double dv) -> Eigen::Vector3d {
    return (8.0 * (m.position(u + du, v + dv) - m.position(u - du, v - dv)) -
            (m.position(u + 2 * du, v + 2 * dv) - m.position(u - 2 * du, v - 2 * dv))) /
           (12 * h);
  };
  const Eigen::Vector3d xu = d(h, 0), xv = d(0, h);
  Eigen::Matrix2d g;
  g << xu.dot(xu), xu.dot(xv), xu.dot(xv), xv.dot(xv);
  return (g - m.g(u, v)).norm() / m.g(u, v).norm();
}
}  // namespace

TEST_CASE("round sphere: area 4 pi R^2, total curvature 4 pi, Brioschi = 1/R^2") {
  const RoundSphereMetric s(2.5);
  CHECK(metricArea(s).value == Approx(4 * M_PI * 2.5 * 2.5).epsilon(1e-12));
  CHECK(metricTotalCurvature(s).value == Approx(4 * M_PI).epsilon(1e-12));
  CHECK(brioschiCurvature(finiteDifferenceJet(s, 1.0, 0.4)) == Approx(1 / 6.25).epsilon(1e-8));
  CHECK(embeddingMismatch(s, 1.0, 0.4) < 1e-9);
  CHECK(*s.geodesicDistance({0, 0}, {1.3, M_PI}) == Approx(M_PI * 2.5).epsilon(1e-15));
}

TEST_CASE("Kerr-Newman horizon: area, equatorial circumference, total curvature at every spin") {
  const double M = 1.3;
  for (double chi : {0.0, 0.3, 0.6, std::sqrt(3.0) / 2, 0.95, 0.999, 1.0}) {
    const double a = chi * M;
    const KerrNewmanMetric k(M, a, 0.0);
    const double rp = M + std::sqrt(M * M - a * a);
    INFO("a/M = " << chi);
    CHECK(k.horizonRadius() == Approx(rp).epsilon(1e-15));
    CHECK(metricArea(k).value == Approx(8 * M_PI * M * rp).epsilon(1e-13));
    CHECK(metricTotalCurvature(k).value == Approx(4 * M_PI).epsilon(1e-13));
    // Equatorial circumference from the metric itself: 2π √g_φφ(θ = π/2) = 4πM for Q = 0.
    CHECK(2 * M_PI * std::sqrt(k.g(0, M_PI / 2)(0, 0)) == Approx(4 * M_PI * M).epsilon(1e-14));
    for (double v : {0.2, 0.9, 1.4, 2.5}) {
      CHECK(brioschiCurvature(finiteDifferenceJet(k, 0, v)) ==
            Approx(k.gaussianCurvature(0, v)).margin(1e-8 / (M * M)));
    }
  }
}

TEST_CASE("Kerr-Newman horizon: K at the poles changes sign at a/M = sqrt(3)/2 (Q = 0)") {
  const double M = 1.0, crit = std::sqrt(3.0) / 2;
  CHECK(KerrNewmanMetric(M, 0.8 * M, 0).gaussianCurvature(0, 0) > 0);
  CHECK(KerrNewmanMetric(M, (crit - 1e-6) * M, 0).gaussianCurvature(0, 0) > 0);
  CHECK(KerrNewmanMetric(M, (crit + 1e-6) * M, 0).gaussianCurvature(0, 0) < 0);
  CHECK(KerrNewmanMetric(M, M, 0).gaussianCurvature(0, M_PI) < 0);
  CHECK(std::abs(KerrNewmanMetric(M, crit * M, 0).gaussianCurvature(0, 0)) < 1e-15);
  // Extremal Kerr: K(pole) = (r₊² + a²)(r₊² − 3a²)/(r₊² + a²)³ = 2M²·(−2M²)/(8M⁶) = −1/(2M²).
  CHECK(KerrNewmanMetric(M, M, 0).gaussianCurvature(0, 0) == Approx(-0.5).epsilon(1e-14));
  // Near the pole Brioschi on the FD jet agrees (the chart is regular there, only the pole point itself is not).
  const KerrNewmanMetric k(M, 0.99, 0);
  CHECK(brioschiCurvature(finiteDifferenceJet(k, 0, 0.05)) == Approx(k.gaussianCurvature(0, 0.05)).epsilon(1e-6));
}

TEST_CASE("Kerr-Newman with charge: area 4 pi (r+^2 + a^2), extremal a^2 + Q^2 = M^2") {
  const double M = 1, a = 0.6, Q = 0.8;  // extremal: 0.36 + 0.64 = 1
  const KerrNewmanMetric k(M, a, Q);
  CHECK(k.horizonRadius() == Approx(1.0).epsilon(1e-15));
  CHECK(metricArea(k).value == Approx(4 * M_PI * (1 + a * a)).epsilon(1e-11));
  CHECK(metricTotalCurvature(k).value == Approx(4 * M_PI).epsilon(1e-11));
  REQUIRE_THROWS_WITH(KerrNewmanMetric(1, 0.8, 0.7), Catch::Contains("kerr-newman") && Catch::Contains("a^2 + Q^2"));
}

TEST_CASE("ellipsoid: K = 1/(rho nu) from GeographicLib, area, conformal chart, embedding") {
  for (double f : {1 / 298.257223563, 0.3, 0.9, 0.99, -0.5, -3.0}) {
    const double a = 6.4;
    INFO("f = " << f);
    const EllipsoidMetric e(a, f);
    const GeographicLib::Ellipsoid ref(a, f);
    for (double phiDeg : {-89.9, -60.0, -10.0, 0.0, 33.0, 75.0, 89.99}) {
      const double theta = e.conformalColatitude(phiDeg * M_PI / 180);
      // dφ/dχ reaches 1/(1 − e²) at the equator, so round-off in χ is amplified by up to (1 − f)⁻² (10⁴ at f = 0.99).
      const double tol = 1e-12 * std::max(1.0, 1 / ((1 - f) * (1 - f)));
      CHECK(e.geographicLatitude(theta) * 180 / M_PI == Approx(phiDeg).margin(tol));
      CHECK(90 - theta * 180 / M_PI == Approx(ref.ConformalLatitude(phiDeg)).margin(tol));
      const double K = 1 / (ref.MeridionalCurvatureRadius(phiDeg) * ref.TransverseCurvatureRadius(phiDeg));
      // 1 − e² = (1 − f)² loses log10(1/(1−f)²) digits of e² (4 at f = 0.99): hence 1e-11, not 1e-13.
      CHECK(e.gaussianCurvature(0.4, theta) == Approx(K).epsilon(1e-11));
      // Brioschi on the fourth-order FD jet of the conformal-chart metric: an independent route to K. Only for moderate
      // flattening: at f = 0.9 the conformal factor varies on a θ-scale ~ b/a near the rim, and FD steps of 2e-3 are
      // no longer small against it (error ~ (h/scale)⁴, smooth_metric.h).
      if (std::abs(phiDeg) < 89 && std::abs(f) <= 0.5)
        CHECK(brioschiCurvature(finiteDifferenceJet(e, 0.4, theta)) == Approx(K).epsilon(2e-8));
    }
    CHECK(e.area() == Approx(ref.Area()).epsilon(1e-13));
    // Measured ≤ 2e-14 up to f = 0.9, 1.6e-12 at f = 0.99 (conditioning of the conformal latitude at the rim).
    CHECK(metricArea(e).value == Approx(ref.Area()).epsilon(1e-11));
    CHECK(metricTotalCurvature(e).value == Approx(4 * M_PI).epsilon(1e-11));
    // The pulled-back embedding equals the conformal-chart metric: this checks the conformal latitude independently
    // of GeographicLib's ConformalLatitude. Central differences with h = 1e-4 err by (h/ℓ)⁴ where ℓ ~ (1 − f) is the
    // θ-scale of the rim, small with this fourth-order stencil; but positions carry round-off amplified by
    // dφ/dχ ~ (1 − f)⁻² near the rim, which divided by h dominates at f = 0.99 (1e-12/1e-4): hence the scaled bound.
    for (double theta : {0.3, 1.2, 1.5, 2.0})
      CHECK(embeddingMismatch(e, 0.7, theta) < 1e-8 * std::max(1.0, 1e-2 / ((1 - f) * (1 - f))));
    // The chart is conformal: g = m² diag(sin²θ, 1).
    const Eigen::Matrix2d g = e.g(0.2, 1.1);
    CHECK(g(0, 1) == 0);
    CHECK(g(0, 0) == Approx(g(1, 1) * std::sin(1.1) * std::sin(1.1)).epsilon(1e-15));
  }
}

TEST_CASE("ellipsoid: exact geodesic distances come from GeodesicExact") {
  const EllipsoidMetric e(1.0, 0.5);
  // Pole to pole along a meridian: twice the quarter meridian, which GeographicLib::Ellipsoid gives independently.
  const GeographicLib::Ellipsoid ref(1.0, 0.5);
  CHECK(*e.geodesicDistance({0.3, 0.0}, {0.3, M_PI}) == Approx(2 * ref.QuarterMeridian()).epsilon(1e-12));
  // Along the equator between nearby points: a (Δλ) (the equator is a geodesic; 0.1 rad is below the conjugate length).
  CHECK(*e.geodesicDistance({0.0, M_PI / 2}, {0.1, M_PI / 2}) == Approx(0.1).epsilon(1e-13));
}

TEST_CASE("ellipsoid: GeodesicExact azimuths agree with the conformal chart's directions") {
  // A geodesic leaving a point with chart direction d has, at that point, the chart azimuth of d. Shoot short chart
  // segments of length h in several directions: the geodesic to their end leaves at the segment's azimuth up to the
  // angle between chord and geodesic, O(h) (chart curves have bounded geodesic curvature). Measured by the slope.
  for (double f : {0.3, -0.5}) {
    const EllipsoidMetric e(1.0, f);
    std::vector<double> hs, errors;
    for (double h : {1e-2, 5e-3, 2.5e-3, 1.25e-3}) {
      double worst = 0;
      for (double dir : {0.3, 1.9, 3.5, 5.0}) {
        const Eigen::Vector2d p(0.4, 1.0), d(std::cos(dir), std::sin(dir));
        const auto inv = e.geodesicInverse(p, p + h * d);
        const double want = EllipsoidMetric::chartAzimuth(p.y(), d.x(), d.y());
        worst = std::max(worst, std::abs(std::remainder(inv.azimuth1 - want, 2 * M_PI)));
      }
      hs.push_back(h), errors.push_back(worst);
    }
    const double order = fitLogLogSlope(hs, errors);
    INFO("f = " << f << ": azimuth error " << errors.front() << " .. " << errors.back() << ", order " << order);
    CHECK(order == Approx(1).margin(0.15));
    CHECK(errors.back() < 1e-3);
  }
}

TEST_CASE("torus: total curvature 0, positive part 4 pi, negative part -4 pi, area 4 pi^2 R r") {
  const double R = 3, r = 1.2;
  const TorusMetric t(R, r);
  CHECK(metricArea(t).value == Approx(4 * M_PI * M_PI * R * r).epsilon(1e-12));
  CHECK(std::abs(metricTotalCurvature(t).value) < 1e-10);
  const ChartFunction kd = curvatureDensity(t);
  CHECK(integrateOverRectangle(kd, 0, 2 * M_PI, -M_PI / 2, M_PI / 2).value == Approx(4 * M_PI).epsilon(1e-12));
  CHECK(integrateOverRectangle(kd, 0, 2 * M_PI, M_PI / 2, 3 * M_PI / 2).value == Approx(-4 * M_PI).epsilon(1e-12));
  for (double v : {0.0, 1.0, 2.5, 4.0}) {
    CHECK(brioschiCurvature(finiteDifferenceJet(t, 0.3, v)) == Approx(t.gaussianCurvature(0.3, v)).margin(1e-9));
    CHECK(embeddingMismatch(t, 0.3, v) < 1e-9);
  }
  CHECK(t.domain().genus() == 1);
  REQUIRE_THROWS_WITH(TorusMetric(1, 2), Catch::Contains("torus") && Catch::Contains("R must exceed"));
}

TEST_CASE("flat torus: area |Im tau| scale^2, K = 0") {
  const FlatTorusMetric t(0.5, 0.8, 2.0);
  CHECK(metricArea(t).value == Approx(0.8 * 4).epsilon(1e-13));
  CHECK(std::abs(brioschiCurvature(finiteDifferenceJet(t, 0.3, 0.6))) < 1e-12);
  CHECK(t.g(0, 0)(0, 1) == Approx(2 * 2 * 0.5));
}

TEST_CASE("spherical cap and hyperbolic disk: area and total curvature in closed form") {
  const double R = 1.7, alpha = 1.1;
  const SphericalCapMetric cap(R, alpha);
  CHECK(metricArea(cap).value == Approx(2 * M_PI * R * R * (1 - std::cos(alpha))).epsilon(1e-12));
  CHECK(metricTotalCurvature(cap).value == Approx(2 * M_PI * (1 - std::cos(alpha))).epsilon(1e-12));
  CHECK(brioschiCurvature(finiteDifferenceJet(cap, 0.5, 0.8)) == Approx(1 / (R * R)).epsilon(1e-8));
  CHECK(embeddingMismatch(cap, 0.5, 0.8) < 1e-9);
  const double r = 2.0;
  const HyperbolicDiskMetric hd(r);
  CHECK(metricArea(hd).value == Approx(4 * M_PI * std::sinh(r / 2) * std::sinh(r / 2)).epsilon(1e-12));
  CHECK(brioschiCurvature(finiteDifferenceJet(hd, 0.5, 0.4)) == Approx(-1).epsilon(1e-8));
  CHECK(*hd.geodesicDistance({0, 0}, {1.0, std::tanh(r / 2)}) == Approx(r).epsilon(1e-14));
}

TEST_CASE("function graph and Bezier patch: K from the second fundamental form") {
  // The Gaussian bump: total curvature over a square whose edge is flat to e^-32 is 0 (Gauss-Bonnet).
  auto bump = makeMetric("gaussian-bump", {{"height", 0.8}, {"width", 0.5}, {"half_extent", 4.0}});
  CHECK(std::abs(metricTotalCurvature(*bump).value) < 1e-9);
  for (double x : {0.0, 0.3, 0.7})
    CHECK(brioschiCurvature(finiteDifferenceJet(*bump, x, 0.2)) ==
          Approx(bump->gaussianCurvature(x, 0.2)).margin(1e-8));
  // Bicubic patch of z = u² + v² over [0,1]² (Bernstein coefficients of t² are 0, 0, 1/3, 1): K = 4/(1+4u²+4v²)².
  BezierControlNet net;
  const double c[4] = {0, 0, 1.0 / 3, 1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) net[i][j] = {i / 3.0, j / 3.0, c[i] + c[j]};
  auto patch = makeBezierPatch("paraboloid", net);
  for (double u : {0.1, 0.5, 0.9})
    for (double v : {0.2, 0.6}) {
      const double w = 1 + 4 * u * u + 4 * v * v;
      CHECK(patch->gaussianCurvature(u, v) == Approx(4 / (w * w)).epsilon(1e-13));
      CHECK(brioschiCurvature(patch->jet(u, v)) == Approx(4 / (w * w)).epsilon(1e-8));
      CHECK((patch->position(u, v) - Eigen::Vector3d(u, v, u * u + v * v)).norm() < 1e-15);
      // g() reads only the tangents: bit for bit the first fundamental form of the full evaluation.
      const SurfaceJet full = evaluateBezierPatch(net, u, v), tangents = evaluateBezierTangents(net, u, v);
      CHECK(tangents.xu == full.xu);
      CHECK(tangents.xv == full.xv);
      Eigen::Matrix2d g;
      g << full.xu.dot(full.xu), full.xu.dot(full.xv), full.xu.dot(full.xv), full.xv.dot(full.xv);
      CHECK(patch->g(u, v) == g);
    }
}

TEST_CASE("ellipsoid: the conformal scale m(theta) against GeographicLib's latitudes, to round-off") {
  // m = nu cos(phi) / cos(chi) at chi = 90 deg - theta. Reference 1: the forward map, chi = ConformalLatitude(phi)
  // (GeographicLib; no inversion), for every f. Reference 2 (oblate only: GeographicLib 2.1.2's tauf is wrong for
  // prolate ellipsoids, metric_families.cpp): phi = InverseConformalLatitude(chi), GeographicLib's own Newton
  // iteration from its own guess. conformalScale starts its Newton step from a fitted sine series instead; both must
  // agree to a few ulps, scaled by the conditioning (1 - f)^-2 of phi(chi) at the rim as in the test above.
  for (double f : {1 / 298.257223563, 0.1, 0.3, 0.6, 0.9, 0.99, -0.5, -3.0}) {
    const double a = 1.7;
    INFO("f = " << f);
    const EllipsoidMetric e(a, f);
    const GeographicLib::Ellipsoid ref(a, f);
    const double tol = 4e-15 * std::max(1.0, 1 / ((1 - f) * (1 - f)));
    double worst2 = 0;
    double worst = 0;
    for (int i = 1; i < 400; ++i) {
      const double phiDeg = -90 + 180.0 * i / 400 + 0.01 * std::sin(i);  // 399 latitudes, not symmetric
      const double chiDeg = ref.ConformalLatitude(phiDeg), theta = (90 - chiDeg) * M_PI / 180;
      const double m1 = ref.TransverseCurvatureRadius(phiDeg) * std::cos(phiDeg * M_PI / 180) / std::sin(theta);
      const double r1 = std::abs(e.conformalScale(theta) / m1 - 1);
      worst = std::max(worst, r1 * std::sin(theta));
      CHECK(r1 <= tol * std::max(1.0, 1 / std::sin(theta)));  // θ in degrees → radians rounds at ~ε/θ near the poles
      if (f > 0 && f <= 0.9) {
        const double phi2 = ref.InverseConformalLatitude(chiDeg);
        const double m2 = ref.TransverseCurvatureRadius(phi2) * std::cos(phi2 * M_PI / 180) / std::sin(theta);
        worst2 = std::max(worst2, std::abs(e.conformalScale(theta) / m2 - 1) * std::sin(theta));
        CHECK(std::abs(e.conformalScale(theta) / m2 - 1) <= tol * std::max(1.0, 1 / std::sin(theta)));
      }
    }
    std::cout << "ellipsoid f=" << f << ": max relative |m - m_ref| " << worst << ", against the inverse " << worst2
              << "\n";
  }
}

TEST_CASE("registry: every family builds with its defaults; bad names and parameters are named") {
  for (const FamilyInfo& f : metricFamilies()) {
    INFO(f.name);
    auto m = makeMetric(f.name);
    CHECK(m->description().find(f.name) != std::string::npos);
    CHECK(std::isfinite(metricArea(*m).value));
  }
  REQUIRE_THROWS_WITH(makeMetric("klein-bottle"), Catch::Contains("unknown metric family 'klein-bottle'"));
  REQUIRE_THROWS_WITH(makeMetric("sphere", {{"radius", 2}}),
                      Catch::Contains("no parameter 'radius'") && Catch::Contains("R"));
  REQUIRE_THROWS_WITH(makeMetric("ellipsoid", {{"f", 1.5}}), Catch::Contains("flattening"));
  REQUIRE_THROWS_WITH(makeMetric("sphere", {{"R", -1}}), Catch::Contains("radius R"));
}
