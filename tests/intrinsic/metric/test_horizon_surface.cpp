// Tests for horizon_surface.h: the real Y_lm against their closed forms and orthonormality (exact Gauss–Legendre
// quadrature), their exact θ/φ derivatives against central differences, the JSON reader's errors, the fit's exactness
// on band-limited shapes, and the induced metric of known horizons: a round sphere in flat space, the isotropic
// Schwarzschild horizon, and the Kerr horizon r = r₊ of Kerr–Schild coordinates (a coordinate spheroid), whose
// intrinsic geometry is Smarr's: area 8πMr₊, K = (r₊² + a²)/r₊⁴ on the equator, (r₊² − 3a²)/(r₊² + a²)² at the poles.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {
int idx(int l, int m) {
  return l * l + l + m;
}
// The Kerr horizon in Kerr–Schild coordinates about its centre: (x² + y²)/(r₊² + a²) + z²/r₊² = 1, as r(θ).
std::function<double(double, double)> kerrSpheroid(double M, double a) {
  const double rp = M + std::sqrt(M * M - a * a), A2 = rp * rp + a * a, C2 = rp * rp;
  return [=](double theta, double) {
    const double s = std::sin(theta), c = std::cos(theta);
    return 1 / std::sqrt(s * s / A2 + c * c / C2);
  };
}
HorizonSurfaceMetric kerrHorizon(double a, int lMax, const Eigen::Vector3d& c = Eigen::Vector3d::Zero()) {
  auto gamma = std::make_shared<KerrSchildMetric>(1.0, a, c);
  return HorizonSurfaceMetric(fitStrahlkorper(kerrSpheroid(1.0, a), lMax, c), gamma);
}
}  // namespace

TEST_CASE("horizon: real Y_lm match their closed forms (no Condon-Shortley phase) and are orthonormal") {
  const double t = 0.7, p = 1.9, k = 1 / std::sqrt(4 * M_PI);
  const auto y = realYlmJets(2, t, p);
  CHECK(y[idx(0, 0)].y == Approx(k).epsilon(1e-15));
  CHECK(y[idx(1, 0)].y == Approx(std::sqrt(3.0) * k * std::cos(t)).epsilon(1e-15));
  CHECK(y[idx(1, 1)].y == Approx(std::sqrt(3.0) * k * std::sin(t) * std::cos(p)).epsilon(1e-15));
  CHECK(y[idx(1, -1)].y == Approx(std::sqrt(3.0) * k * std::sin(t) * std::sin(p)).epsilon(1e-15));
  CHECK(y[idx(2, 0)].y == Approx(std::sqrt(5.0) * k * (3 * std::cos(t) * std::cos(t) - 1) / 2).epsilon(1e-14));
  CHECK(y[idx(2, 2)].y == Approx(std::sqrt(15.0 / 4) * k * std::pow(std::sin(t), 2) * std::cos(2 * p)).epsilon(1e-14));
  CHECK(y[idx(2, -1)].y == Approx(std::sqrt(15.0) * k * std::sin(t) * std::cos(t) * std::sin(p)).epsilon(1e-14));
  // Orthonormality by a product rule exact for degree ≤ 2L: L + 1 Gauss–Legendre nodes in cos θ, 2L + 2 in φ.
  const int L = 8, nt = L + 1, np = 2 * L + 2;
  std::vector<double> x, w;
  gaussLegendre(nt, x, w);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero((L + 1) * (L + 1), (L + 1) * (L + 1));
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const auto Y = realYlmJets(L, std::acos(x[i]), 2 * M_PI * j / np);
      Eigen::VectorXd v(Y.size());
      for (std::size_t n = 0; n < Y.size(); ++n) v[n] = Y[n].y;
      gram += w[i] * 2 * M_PI / np * v * v.transpose();
    }
  CHECK((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff() < 1e-13);
}

TEST_CASE("horizon: Y_lm derivatives agree with central differences") {
  // Fourth-order differences with h = 1e-3: truncation ~ h⁴ l⁵ ≈ 1e-6 at l = 16 (relative to the size l² of the
  // second derivatives), round-off ~ ε l²/h² ≈ 6e-8.
  const int L = 16;
  const double t = 1.1, p = 0.4, h = 1e-3;
  auto d4 = [&](auto f) { return (8 * (f(h) - f(-h)) - (f(2 * h) - f(-2 * h))) / (12 * h); };
  const auto y = realYlmJets(L, t, p);
  for (int l = 0; l <= L; ++l)
    for (int m = -l; m <= l; ++m) {
      const int n = idx(l, m);
      const double s = 1 + l * l;
      INFO("l=" << l << " m=" << m);
      CHECK(std::abs(d4([&](double e) { return realYlmJets(L, t + e, p)[n].y; }) - y[n].yt) < 1e-7 * s);
      CHECK(std::abs(d4([&](double e) { return realYlmJets(L, t, p + e)[n].y; }) - y[n].yp) < 1e-7 * s);
      CHECK(std::abs(d4([&](double e) { return realYlmJets(L, t + e, p)[n].yt; }) - y[n].ytt) < 1e-6 * s);
      CHECK(std::abs(d4([&](double e) { return realYlmJets(L, t, p + e)[n].yt; }) - y[n].ytp) < 1e-6 * s);
      CHECK(std::abs(d4([&](double e) { return realYlmJets(L, t, p + e)[n].yp; }) - y[n].ypp) < 1e-6 * s);
    }
}

TEST_CASE("horizon: the fit recovers band-limited shapes exactly and JSON round-trips") {
  const Strahlkorper s(Eigen::Vector3d(0.1, 0.2, 0.3),
                       {{0, 0, 3.0}, {2, 1, 0.1}, {3, -2, -0.05}, {4, 0, 0.02}, {5, 5, 0.01}});
  const Strahlkorper f = fitStrahlkorper([&](double t, double p) { return s.radius(t, p).r; }, 6, s.center());
  for (int l = 0; l <= 6; ++l)
    for (int m = -l; m <= l; ++m) CHECK(std::abs(f.coefficient(l, m) - s.coefficient(l, m)) < 1e-14);
  const Strahlkorper back = parseStrahlkorperJson(strahlkorperToJson(f), "round-trip");
  CHECK(back.center() == f.center());
  for (int l = 0; l <= 6; ++l)
    for (int m = -l; m <= l; ++m) CHECK(back.coefficient(l, m) == f.coefficient(l, m));
  // The Condon–Shortley convention flips odd m.
  const Strahlkorper cs = parseStrahlkorperJson(
      R"({"center":[0,0,0],"convention":"orthonormal-condon-shortley","coefficients":[[0,0,3],[1,1,0.2],[2,2,0.1]]})",
      "cs.json");
  CHECK(cs.coefficient(1, 1) == -0.2);
  CHECK(cs.coefficient(2, 2) == 0.1);
}

TEST_CASE("horizon: malformed shape files are named") {
  auto bad = [](const std::string& text, const std::string& what) {
    CHECK_THROWS_WITH(parseStrahlkorperJson(text, "h.json"), Catch::StartsWith("h.json: ") && Catch::Contains(what));
  };
  bad("{", "not valid JSON");
  bad(R"({"coefficients":[[0,0,1]]})", "missing key 'center'");
  bad(R"({"center":[0,0]})", "missing key 'coefficients'");
  bad(R"({"center":[0,0],"coefficients":[[0,0,1]]})", "'center': expected [x, y, z]");
  bad(R"({"center":[0,0,0],"coefficients":[[0,0,1],[1,"a",2]]})", "coefficients[1]");
  bad(R"({"center":[0,0,0],"coefficients":[[0,0,1],[1,2,0.1]]})", "|m| <= l");
  bad(R"({"center":[0,0,0],"coefficients":[[0,0,1],[0,0,2]]})", "given twice");
  bad(R"({"center":[0,0,0],"coefficients":[[0,0,-1]]})", "radius must be positive");
  bad(R"({"center":[0,0,0],"coefficients":[[0,0,1]],"convention":"spherepack"})", "unknown spherical-harmonic");
  CHECK_THROWS_WITH(readStrahlkorperJson("/nonexistent/h.json"), Catch::Contains("cannot open"));
}

TEST_CASE("horizon: round spheres in flat space and the isotropic Schwarzschild horizon") {
  const double R = 1.7;
  const Strahlkorper sphere(Eigen::Vector3d(1, 2, 3), {{0, 0, R * std::sqrt(4 * M_PI)}});
  const HorizonSurfaceMetric flat(sphere, std::make_shared<FlatSpatialMetric>());
  const Eigen::Matrix2d g = flat.g(0.3, 1.2);
  CHECK(g(0, 0) == Approx(R * R * std::pow(std::sin(1.2), 2)).epsilon(1e-14));
  CHECK(g(1, 1) == Approx(R * R).epsilon(1e-14));
  CHECK(std::abs(g(0, 1)) < 1e-14);
  CHECK(flat.gaussianCurvature(0.3, 1.2) == Approx(1 / (R * R)).epsilon(1e-8));
  // Isotropic Schwarzschild, M = 1: the horizon ρ = M/2 has area 16πM².
  const Strahlkorper h(Eigen::Vector3d::Zero(), {{0, 0, 0.5 * std::sqrt(4 * M_PI)}});
  const HorizonSurfaceMetric s(h, std::make_shared<IsotropicSchwarzschildMetric>(1, Eigen::Vector3d::Zero()));
  CHECK(metricArea(s).value == Approx(16 * M_PI).epsilon(1e-10));
}

TEST_CASE("horizon: analytic first derivatives of the induced metric agree with fourth-order differences") {
  // A non-axisymmetric shape in a translated Kerr–Schild γ: every term of g_ab,c contributes.
  const Eigen::Vector3d c(0.2, -0.1, 0.3);
  const Strahlkorper s(c, {{0, 0, 2.2 * std::sqrt(4 * M_PI)}, {1, 1, 0.1}, {2, -1, 0.15}, {3, 2, -0.08}});
  const HorizonSurfaceMetric m(s, std::make_shared<KerrSchildMetric>(1.0, 0.8, c));
  for (const Eigen::Vector2d p : {Eigen::Vector2d(0.4, 0.9), Eigen::Vector2d(3.5, 2.2), Eigen::Vector2d(5.9, 0.2)}) {
    const MetricJet a = m.jet(p.x(), p.y()), f = finiteDifferenceJet(m, p.x(), p.y());
    // finiteDifferenceJet's truncation (~1e-12 on first, ~3e-10 on second derivatives; smooth_metric.h) and the
    // jet's own differences of analytic first derivatives (~1e-12).
    CHECK((a.gu - f.gu).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((a.gv - f.gv).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((a.guu - f.guu).cwiseAbs().maxCoeff() < 1e-7);
    CHECK((a.guv - f.guv).cwiseAbs().maxCoeff() < 1e-7);
    CHECK((a.gvv - f.gvv).cwiseAbs().maxCoeff() < 1e-7);
  }
}

TEST_CASE("horizon: the Kerr horizon of Kerr-Schild coordinates has Smarr's area, falling spectrally in l_max") {
  for (double a : {0.8, 0.95})
    for (const Eigen::Vector3d& c : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.7, -1.3, 2.1)}) {
      const double rp = 1 + std::sqrt(1 - a * a), exact = 8 * M_PI * rp;
      std::vector<double> errors;
      for (int lMax : {8, 16, 24}) {
        QuadratureOptions q;
        q.relativeTolerance = 1e-13, q.absoluteTolerance = 1e-13;
        errors.push_back(std::abs(metricArea(kerrHorizon(a, lMax, c), q).value - exact) / exact);
      }
      UNSCOPED_INFO("a=" << a << " centre " << c.transpose() << ": relative area errors " << errors[0] << " " << errors[1]
                << " " << errors[2]);
      // Spectral: each step of 8 in l_max gains at least a factor 30 until round-off (~1e-13 of the quadrature);
      // an algebraic rate of order p would gain only 2^p, 1.5^p.
      CHECK(errors[0] < 1e-3);
      CHECK((errors[1] < errors[0] / 30 || errors[1] < 1e-12));
      CHECK((errors[2] < errors[1] / 30 || errors[2] < 1e-12));
      CHECK(errors[2] < 1e-8);
    }
}

TEST_CASE("horizon: the Kerr horizon's Gaussian curvature is Smarr's on the equator and at the poles") {
  const double a = 0.95, rp = 1 + std::sqrt(1 - a * a), s = rp * rp + a * a;
  const HorizonSurfaceMetric m = kerrHorizon(a, 24);
  // Brioschi on the jet: second derivatives by differences (~1e-10) and a fit error at l_max = 24 (~1e-9).
  CHECK(m.gaussianCurvature(1.0, M_PI / 2) == Approx(s / (rp * rp * rp * rp)).epsilon(1e-6));
  CHECK(m.gaussianCurvature(2.0, 1e-5) == Approx((rp * rp - 3 * a * a) / (s * s)).epsilon(1e-4));
}
