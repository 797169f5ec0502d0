// smooth_metric.cpp — chart shapes, the pole-free reference surfaces of polar charts, finite-difference metric jets and
// Brioschi's curvature formula (see smooth_metric.h).
#include "conformesh/intrinsic/metric/smooth_metric.h"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

// =====================================================================================================================
// chart

ChartShape ChartDomain::shape() const {
  if (periodicU && periodicV) return ChartShape::Torus;
  if (periodicU && poleAtV0 && poleAtV1) return ChartShape::Sphere;
  if (periodicU && poleAtV0) return ChartShape::Disk;
  if (periodicU) return ChartShape::Cylinder;
  return ChartShape::Rectangle;
}

int ChartDomain::boundaryLoops() const {
  switch (shape()) {
    case ChartShape::Torus:
    case ChartShape::Sphere:
      return 0;
    case ChartShape::Cylinder:
      return 2;
    case ChartShape::Disk:
    case ChartShape::Rectangle:
      return 1;
  }
  return 1;
}

std::string toString(ChartShape s) {
  switch (s) {
    case ChartShape::Rectangle:
      return "rectangle";
    case ChartShape::Cylinder:
      return "cylinder";
    case ChartShape::Torus:
      return "torus";
    case ChartShape::Disk:
      return "disk";
    case ChartShape::Sphere:
      return "sphere";
  }
  return "rectangle";
}

Eigen::Vector3d referencePoint(const ChartDomain& d, double u, double v) {
  switch (d.shape()) {
    case ChartShape::Sphere:
      return {std::sin(v) * std::cos(u), std::sin(v) * std::sin(u), std::cos(v)};
    case ChartShape::Disk:
      return {v * std::cos(u), v * std::sin(u), 0.0};
    default:
      return {u, v, 0.0};
  }
}

Eigen::Vector2d chartPoint(const ChartDomain& d, const Eigen::Vector3d& x, const Eigen::Vector3d& dx,
                           Eigen::Vector2d* duv) {
  const ChartShape s = d.shape();
  if (s != ChartShape::Sphere && s != ChartShape::Disk) {
    if (duv) *duv = dx.head<2>();
    return x.head<2>();
  }
  // Polar charts: the angle u from atan2 (wrapped to [0, 2π)), v the polar angle (sphere; x need not be normalized,
  // only its direction counts, so a chord of the sphere parametrizes the great arc) or the radius (disk).
  const double rho = std::hypot(x.x(), x.y());
  double u = std::atan2(x.y(), x.x());
  if (u < 0) u += 2 * M_PI;
  if (rho == 0) u = 0;
  const double v = s == ChartShape::Sphere ? std::atan2(rho, x.z()) : rho;
  if (duv) {
    const double rho2 = rho * rho;
    const double du = (x.x() * dx.y() - x.y() * dx.x()) / rho2;
    const double drho = (x.x() * dx.x() + x.y() * dx.y()) / rho;
    const double dv = s == ChartShape::Sphere ? (x.z() * drho - rho * dx.z()) / (rho2 + x.z() * x.z()) : drho;
    *duv = {du, dv};
  }
  return {u, v};
}

// =====================================================================================================================
// metric

double SmoothMetric::areaElement(double u, double v) const {
  const Eigen::Matrix2d m = g(u, v);
  return std::sqrt(std::max(0.0, m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0)));
}

MetricJet SmoothMetric::jet(double u, double v) const {
  return finiteDifferenceJet(*this, u, v);
}

double SmoothMetric::gaussianCurvature(double u, double v) const {
  const ChartDomain d = domain();
  // Brioschi's formula divides by (EG − F²)², which vanishes at a coordinate pole (g_uu ~ sin²v), and loses accuracy
  // like ε/dist² next to one. Within the band dist < δ = 1e-3·w of a pole (w = the chart scale of smooth_metric.h), K
  // is interpolated linearly in dist between its limit at the pole and Brioschi's value at (u, δ): error ≈ δ²|K_vv|/8
  // ≈ 1e-7 relative for K varying on the chart's scale. The limit: in polar coordinates about the pole K = K₀ +
  // dist·(a cos u + b sin u) + dist²·(c + periodic terms in 2u) + O(dist³), so the mean over 8 equally spaced u kills
  // the linear and 2u terms, and Richardson on the means at δ and 2δ leaves O(δ⁴) truncation (round-off: analytic
  // jets ε/δ² ≈ 1e-10, finite-difference jets ≈ 3e-11/δ² ≈ 3e-5 relative).
  const double w = std::min(d.u1 - d.u0, d.v1 - d.v0) / M_PI, delta = 1e-3 * w;
  for (int end = 0; end < 2; ++end) {
    if (!(end == 0 ? d.poleAtV0 : d.poleAtV1)) continue;
    const double pole = end == 0 ? d.v0 : d.v1, side = end == 0 ? 1 : -1, dist = side * (v - pole);
    if (!(dist < delta)) continue;
    auto meanAt = [&](double r) {
      double sum = 0;
      for (int k = 0; k < 8; ++k) sum += brioschiCurvature(jet(d.u0 + k * (d.u1 - d.u0) / 8, pole + side * r));
      return sum / 8;
    };
    const double k0 = (4 * meanAt(delta) - meanAt(2 * delta)) / 3;
    const double t = std::max(dist, 0.0) / delta;
    return t == 0 ? k0 : k0 + t * (brioschiCurvature(jet(u, pole + side * delta)) - k0);
  }
  return brioschiCurvature(jet(u, v));
}

Eigen::Vector3d SmoothMetric::position(double, double) const {
  throw InputError(description() + ": this metric has no embedding in R^3 (no positions can be written)");
}

std::optional<double> SmoothMetric::geodesicDistance(const Eigen::Vector2d&, const Eigen::Vector2d&) const {
  return std::nullopt;
}

MetricJet finiteDifferenceJet(const SmoothMetric& m, double u, double v) {
  const ChartDomain d = m.domain();
  const double w = std::min(d.u1 - d.u0, d.v1 - d.v0) / M_PI;
  const double h1 = 1e-3 * w, h2 = 2e-3 * w;  // see smooth_metric.h for the error budget
  // Both return a Matrix2d (not an Eigen expression, which would refer to the destroyed temporaries f(·)).
  auto d1 = [](auto f, double h) -> Eigen::Matrix2d {  // fourth-order first derivative along a direction
    return ((f(-2 * h) - f(2 * h)) + 8.0 * (f(h) - f(-h))) / (12 * h);
  };
  auto d2 = [](auto f, double h) -> Eigen::Matrix2d {  // fourth-order second derivative
    return (-(f(2 * h) + f(-2 * h)) + 16.0 * (f(h) + f(-h)) - 30.0 * f(0.0)) / (12 * h * h);
  };
  MetricJet j;
  j.g = m.g(u, v);
  auto alongU = [&](double vv) { return [&m, u, vv](double t) -> Eigen::Matrix2d { return m.g(u + t, vv); }; };
  auto alongV = [&](double uu) { return [&m, v, uu](double t) -> Eigen::Matrix2d { return m.g(uu, v + t); }; };
  j.gu = d1(alongU(v), h1);
  j.gv = d1(alongV(u), h1);
  j.guu = d2(alongU(v), h2);
  j.gvv = d2(alongV(u), h2);
  // Mixed derivative: the first-derivative stencil in v applied to the first-derivative stencil in u.
  auto guAt = [&](double t) -> Eigen::Matrix2d { return d1(alongU(v + t), h2); };
  j.guv = d1(guAt, h2);
  return j;
}

double brioschiCurvature(const MetricJet& j) {
  const double E = j.g(0, 0), F = j.g(0, 1), G = j.g(1, 1);
  const double Eu = j.gu(0, 0), Ev = j.gv(0, 0), Fu = j.gu(0, 1), Fv = j.gv(0, 1), Gu = j.gu(1, 1), Gv = j.gv(1, 1);
  const double Evv = j.gvv(0, 0), Fuv = j.guv(0, 1), Guu = j.guu(1, 1);
  Eigen::Matrix3d a, b;
  a << -0.5 * Evv + Fuv - 0.5 * Guu, 0.5 * Eu, Fu - 0.5 * Ev,  //
      Fv - 0.5 * Gu, E, F,                                     //
      0.5 * Gv, F, G;
  b << 0, 0.5 * Ev, 0.5 * Gu,  //
      0.5 * Ev, E, F,          //
      0.5 * Gu, F, G;
  const double det = E * G - F * F;
  return (a.determinant() - b.determinant()) / (det * det);
}

void checkPositiveDefinite(const Eigen::Matrix2d& g, const std::string& where) {
  const double E = g(0, 0), F = g(0, 1), G = g(1, 1);
  if (!std::isfinite(E) || !std::isfinite(F) || !std::isfinite(G) || !std::isfinite(g(1, 0))) {
    std::ostringstream s;
    s << where << ": metric component is not finite (g_uu=" << E << ", g_uv=" << F << ", g_vv=" << G << ")";
    throw InputError(s.str());
  }
  if (!(E > 0) || !(G > 0) || !(E * G - F * F > 0)) {
    std::ostringstream s;
    s << where << ": metric is not positive definite (g_uu=" << E << ", g_uv=" << F << ", g_vv=" << G
      << ", det=" << E * G - F * F << "; expected g_uu > 0 and det > 0)";
    throw InputError(s.str());
  }
}

}  // namespace conformesh::intrinsic
