// metric_families.cpp — the built-in metric families (see metric_families.h; formulas derived in docs/metrics.md).
// The name registry that builds them from parameters is metric_registry.cpp.
#include "conformesh/intrinsic/metric/metric_families.h"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>
#include <GeographicLib/GeodesicExact.hpp>
#include <GeographicLib/Math.hpp>

#include "conformesh/intrinsic/errors.h"
#include "metric/family_checks.h"

namespace conformesh::intrinsic {

namespace {

using metric_detail::fmt;
using metric_detail::require;

ChartDomain sphereChart() {
  ChartDomain d;
  d.u0 = 0, d.u1 = 2 * M_PI, d.v0 = 0, d.v1 = M_PI;
  d.periodicU = true, d.poleAtV0 = true, d.poleAtV1 = true;
  return d;
}

ChartDomain diskChart(double radius) {
  ChartDomain d;
  d.u0 = 0, d.u1 = 2 * M_PI, d.v0 = 0, d.v1 = radius;
  d.periodicU = true, d.poleAtV0 = true;
  return d;
}

// Angle between the unit-sphere directions of two chart points, by atan2(|a×b|, a·b) (accurate for tiny angles).
double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// tan φ from tan χ (conformal latitude χ) by Newton's method on GeographicLib's Math::taupf, with Karney's derivative
// dτ'/dτ = (1 − e²) √(1 + τ'²) √(1 + τ²) / (1 + (1 − e²) τ²) (Karney 2011, eq. 19–21). Math::tauf itself forms
// 1 − e² as 1 − es², which is wrong for prolate ellipsoids (e² < 0) and fails to converge there (round trips off by
// tens of degrees at f = −0.5 in GeographicLib 2.1.2); this uses e² itself.
// Round trips taupf∘τ agree to a relative 1e-15 over f ∈ [−98, 0.3] (4e-12 at f = 0.99, the conditioning of τ(τ'));
// 100 iterations is a hard cap, never reached.
double newtonTau(double taup, double tau, double e2, double es) {
  const double e2m = 1 - e2;
  for (int i = 0; i < 100; ++i) {
    const double tp = GeographicLib::Math::taupf(tau, es);
    const double dtau = (taup - tp) * (1 + e2m * tau * tau) / (e2m * std::hypot(1.0, tau) * std::hypot(1.0, tp));
    tau += dtau;
    // Newton converges quadratically: once a step is below √ε·|τ| the updated τ is at round-off (Karney's criterion).
    if (!(std::abs(dtau) >= 1.5e-8 * std::max(1.0, std::abs(tau)))) break;
  }
  return tau;
}
double tauFromTaup(double taup, double e2, double es) {
  // Start from Math::tauf where it is right (oblate: within ~1e-12, so one Newton step polishes it), else from
  // Karney's own initial guess.
  const double tau = e2 >= 0               ? GeographicLib::Math::tauf(taup, es)
                     : std::abs(taup) > 70 ? taup * std::exp(GeographicLib::Math::eatanhe(1.0, es))
                                           : taup / (1 - e2);
  return newtonTau(taup, tau, e2, es);
}

// The sine coefficients b_k (k = 1..K) of φ − χ, odd and π-periodic in the conformal latitude χ, by trigonometric
// interpolation of the exact inversion at N = 128 points χ_j = πj/N of one period: b_k = (2/N) Σ_j (φ − χ)(χ_j)
// sin 2kχ_j, exact for a series of degree < N/2 (aliasing from the dropped b_{N±k} only). Trailing |b_k| < 1e-17 are
// dropped. The series is only a Newton guess: it is kept when it matches the exact inversion to 1e-9 at the N/2
// midpoints of (0, π/2), so that one Newton step lands at round-off; otherwise (|f| near 1, strongly prolate: slow
// convergence) the result is empty and conformalScale keeps GeographicLib's guess.
std::vector<double> conformalLatitudeSeries(double e2, double es) {
  const int N = 128;
  auto deviation = [&](double chi) {  // φ − χ at χ ∈ (−π/2, π/2)
    return std::atan(tauFromTaup(std::tan(chi), e2, es)) - chi;
  };
  std::vector<double> f(N, 0.0);
  for (int j = 0; j < N; ++j)
    if (2 * j != N) f[j] = deviation(j < N / 2 ? M_PI * j / N : M_PI * j / N - M_PI);
  std::vector<double> b(N / 2 - 1, 0.0);
  for (int k = 1; k < N / 2; ++k) {
    double sum = 0;
    for (int j = 0; j < N; ++j) sum += f[j] * std::sin(2 * k * M_PI * j / N);
    b[k - 1] = 2 * sum / N;
  }
  while (!b.empty() && std::abs(b.back()) < 1e-17) b.pop_back();
  for (int j = 0; j < N / 2; ++j) {
    const double chi = M_PI * (j + 0.5) / N;
    double series = 0;
    for (size_t k = 0; k < b.size(); ++k) series += b[k] * std::sin(2 * (k + 1) * chi);
    if (!(std::abs(series - deviation(chi)) <= 1e-9)) return {};
  }
  return b;
}

// tan φ at conformal colatitude θ = π/2 − χ (s = sin θ > 0, c = cos θ) from the series: δ = φ − χ by Clenshaw's
// recurrence in sin 2kχ (sin 2χ = 2sc, cos 2χ = s² − c², no further trigonometry), then tan(χ + δ) =
// (c + s tan δ) / (s − c tan δ).
double seriesTau(const std::vector<double>& b, double s, double c) {
  const double sin2 = 2 * s * c, cos2 = s * s - c * c;
  double y1 = 0, y2 = 0;
  for (size_t k = b.size(); k-- > 0;) {
    const double y = b[k] + 2 * cos2 * y1 - y2;
    y2 = y1, y1 = y;
  }
  const double t = std::tan(y1 * sin2);
  return (c + s * t) / (s - c * t);
}

// Fourth-order central difference of a matrix-valued function of one variable (used for second derivatives of g from
// analytic first derivatives; step 2e-3 of the chart width, error budget in smooth_metric.h).
template <class F>
Eigen::Matrix2d centralDifference(F f, double h) {
  return ((f(-2 * h) - f(2 * h)) + 8.0 * (f(h) - f(-h))) / (12 * h);
}

}  // namespace

// =====================================================================================================================
// round sphere

RoundSphereMetric::RoundSphereMetric(double radius) : R_(radius) {
  require(std::isfinite(radius) && radius > 0, "sphere", "radius R must be finite and > 0, found " + fmt(radius));
}
std::string RoundSphereMetric::description() const {
  return "sphere R=" + fmt(R_);
}
ChartDomain RoundSphereMetric::domain() const {
  return sphereChart();
}
Eigen::Matrix2d RoundSphereMetric::g(double, double v) const {
  const double s = std::sin(v);
  return Eigen::Vector2d(R_ * R_ * s * s, R_ * R_).asDiagonal();
}
MetricJet RoundSphereMetric::jet(double u, double v) const {
  MetricJet j;
  j.g = g(u, v);
  j.gu.setZero(), j.guu.setZero(), j.guv.setZero(), j.gv.setZero(), j.gvv.setZero();
  j.gv(0, 0) = R_ * R_ * std::sin(2 * v);
  j.gvv(0, 0) = 2 * R_ * R_ * std::cos(2 * v);
  return j;
}
Eigen::Vector3d RoundSphereMetric::position(double u, double v) const {
  return R_ * referencePoint(domain(), u, v);
}
std::optional<double> RoundSphereMetric::geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const ChartDomain d = domain();
  return R_ * angleBetween(referencePoint(d, a.x(), a.y()), referencePoint(d, b.x(), b.y()));
}

// =====================================================================================================================
// ellipsoid of revolution

EllipsoidMetric::EllipsoidMetric(double a, double f) : a_(a), f_(f) {
  require(std::isfinite(a) && a > 0, "ellipsoid", "equatorial radius a must be finite and > 0, found " + fmt(a));
  // GeodesicExact is documented accurate for −99 ≤ f ≤ 0.99; beyond, the ellipsoid is a needle or a disk.
  require(std::isfinite(f) && f > -99 && f <= 0.99, "ellipsoid",
          "flattening f must lie in (-99, 0.99] (GeographicLib GeodesicExact's range), found " + fmt(f));
  e2_ = f * (2 - f);
  es_ = (f < 0 ? -1 : 1) * std::sqrt(std::abs(e2_));
  geodesic_ = std::make_shared<GeographicLib::GeodesicExact>(a, f);
  latitudeSeries_ = conformalLatitudeSeries(e2_, es_);
}
std::string EllipsoidMetric::description() const {
  return "ellipsoid a=" + fmt(a_) + " f=" + fmt(f_);
}
ChartDomain EllipsoidMetric::domain() const {
  return sphereChart();
}

double EllipsoidMetric::geographicLatitude(double theta) const {
  if (std::sin(theta) == 0) return std::cos(theta) > 0 ? M_PI / 2 : -M_PI / 2;  // the poles themselves
  // tan χ = cot θ; φ = atan(τ(tan χ)) keeps full relative accuracy of cos φ near the poles.
  const double taup = std::cos(theta) / std::sin(theta);
  return std::atan(tauFromTaup(taup, e2_, es_));
}
double EllipsoidMetric::conformalColatitude(double phi) const {
  const double taup = GeographicLib::Math::taupf(std::tan(phi), es_);
  return std::atan2(1.0, taup);
}
double EllipsoidMetric::conformalScale(double theta) const {
  // m is an even function of θ about each pole (the chart is a polar chart), which is how FD stencils that step past
  // a pole are answered.
  theta = std::fmod(std::abs(theta), 2 * M_PI);
  if (theta > M_PI) theta = 2 * M_PI - theta;
  const double s = std::sin(theta);
  // At the pole m → ν(90°) · exp(−e atanh e) (the limit of cos φ / cos χ, GeographicLib's polar stereographic scale);
  // below θ = 1e-12 the O(θ²) difference is below 1e-24 relative.
  if (s < 1e-12) return a_ / std::sqrt(1 - e2_) * std::exp(-GeographicLib::Math::eatanhe(1.0, es_));
  const double c = std::cos(theta), taup = c / s;
  const double guess = latitudeSeries_.empty() ? NAN : seriesTau(latitudeSeries_, s, c);
  // A guess of the wrong sign (never seen; τ and τ' share their sign) or not finite falls back to GeographicLib's.
  const double tau =
      std::isfinite(guess) && guess * taup >= 0 ? newtonTau(taup, guess, e2_, es_) : tauFromTaup(taup, e2_, es_);
  const double cphi = 1 / std::hypot(1.0, tau), sphi = tau * cphi;
  const double nu = a_ / std::sqrt(1 - e2_ * sphi * sphi);
  return nu * cphi / s;
}
Eigen::Matrix2d EllipsoidMetric::g(double, double v) const {
  const double m = conformalScale(v), s = std::sin(v);
  return Eigen::Vector2d(m * m * s * s, m * m).asDiagonal();
}
double EllipsoidMetric::gaussianCurvature(double, double v) const {
  const double sphi = std::sin(geographicLatitude(v));
  const double w = 1 - e2_ * sphi * sphi;
  return w * w / (a_ * a_ * (1 - e2_));
}
Eigen::Vector3d EllipsoidMetric::position(double u, double v) const {
  const double phi = geographicLatitude(v);
  const double sphi = std::sin(phi), cphi = std::cos(phi);
  const double nu = a_ / std::sqrt(1 - e2_ * sphi * sphi);
  return {nu * cphi * std::cos(u), nu * cphi * std::sin(u), nu * (1 - e2_) * sphi};
}
std::optional<double> EllipsoidMetric::geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const double r2d = 180 / M_PI;
  double s12 = 0;
  geodesic_->Inverse(geographicLatitude(a.y()) * r2d, a.x() * r2d, geographicLatitude(b.y()) * r2d, b.x() * r2d, s12);
  return s12;
}
EllipsoidMetric::GeodesicInverse EllipsoidMetric::geodesicInverse(const Eigen::Vector2d& a,
                                                                  const Eigen::Vector2d& b) const {
  const double r2d = 180 / M_PI;
  double s12 = 0, azi1 = 0, azi2 = 0;
  geodesic_->Inverse(geographicLatitude(a.y()) * r2d, a.x() * r2d, geographicLatitude(b.y()) * r2d, b.x() * r2d, s12,
                     azi1, azi2);
  return {s12, azi1 / r2d, azi2 / r2d};
}
double EllipsoidMetric::area() const {
  if (e2_ == 0) return 4 * M_PI * a_ * a_;
  // S = 2πa² (1 + (1 − e²) atanh(e)/e), continued analytically to prolate (e² < 0: atan(|e|)/|e|) by eatanhe.
  return 2 * M_PI * a_ * a_ * (1 + (1 - e2_) * GeographicLib::Math::eatanhe(1.0, es_) / e2_);
}

// =====================================================================================================================
// Kerr–Newman horizon

KerrNewmanMetric::KerrNewmanMetric(double M, double a, double Q) : M_(M), a_(a), Q_(Q) {
  require(std::isfinite(M) && M > 0, "kerr-newman", "mass M must be finite and > 0, found " + fmt(M));
  require(std::isfinite(a) && std::isfinite(Q), "kerr-newman", "spin a and charge Q must be finite");
  const double disc = M * M - a * a - Q * Q;
  // Extremal horizons (disc = 0) are allowed; a relative round-off of 1e-14 in a² + Q² is forgiven so that a = M
  // typed as a decimal is accepted.
  require(disc >= -1e-14 * M * M, "kerr-newman",
          "a^2 + Q^2 must not exceed M^2 (no horizon: naked singularity), found a=" + fmt(a) + " Q=" + fmt(Q) +
              " M=" + fmt(M));
  rp_ = M + std::sqrt(std::max(0.0, disc));
}
std::string KerrNewmanMetric::description() const {
  return "kerr-newman M=" + fmt(M_) + " a=" + fmt(a_) + " Q=" + fmt(Q_);
}
ChartDomain KerrNewmanMetric::domain() const {
  return sphereChart();
}
Eigen::Matrix2d KerrNewmanMetric::g(double, double v) const {
  const double s = rp_ * rp_ + a_ * a_, c = std::cos(v), sn = std::sin(v);
  const double rho2 = rp_ * rp_ + a_ * a_ * c * c;
  return Eigen::Vector2d(s * s * sn * sn / rho2, rho2).asDiagonal();
}
MetricJet KerrNewmanMetric::jet(double u, double v) const {
  // E = ρ², G = s² S / E with S = sin²θ; derivatives in θ only (docs/metrics.md).
  const double s = rp_ * rp_ + a_ * a_, a2 = a_ * a_;
  const double E = rp_ * rp_ + a2 * std::cos(v) * std::cos(v);
  const double E1 = -a2 * std::sin(2 * v), E2 = -2 * a2 * std::cos(2 * v);
  const double S = std::sin(v) * std::sin(v), S1 = std::sin(2 * v), S2 = 2 * std::cos(2 * v);
  const double G1 = s * s * (S1 * E - S * E1) / (E * E);
  const double G2 = s * s * ((S2 * E - S * E2) / (E * E) - 2 * E1 * (S1 * E - S * E1) / (E * E * E));
  MetricJet j;
  j.g = g(u, v);
  j.gu.setZero(), j.guu.setZero(), j.guv.setZero();
  j.gv = Eigen::Vector2d(G1, E1).asDiagonal();
  j.gvv = Eigen::Vector2d(G2, E2).asDiagonal();
  return j;
}
double KerrNewmanMetric::gaussianCurvature(double, double v) const {
  const double s = rp_ * rp_ + a_ * a_, c = std::cos(v);
  const double rho2 = rp_ * rp_ + a_ * a_ * c * c;
  return s * (rp_ * rp_ - 3 * a_ * a_ * c * c) / (rho2 * rho2 * rho2);
}
double KerrNewmanMetric::area() const {
  return 4 * M_PI * (rp_ * rp_ + a_ * a_);
}
double KerrNewmanMetric::equatorialCircumference() const {
  return 2 * M_PI * (rp_ * rp_ + a_ * a_) / rp_;
}

// =====================================================================================================================
// torus of revolution

TorusMetric::TorusMetric(double R, double r) : R_(R), r_(r) {
  require(std::isfinite(r) && r > 0, "torus", "tube radius r must be finite and > 0, found " + fmt(r));
  require(std::isfinite(R) && R > r, "torus",
          "centre-circle radius R must exceed the tube radius r (else the torus self-intersects), found R=" + fmt(R) +
              " r=" + fmt(r));
}
std::string TorusMetric::description() const {
  return "torus R=" + fmt(R_) + " r=" + fmt(r_);
}
ChartDomain TorusMetric::domain() const {
  ChartDomain d;
  d.u0 = 0, d.u1 = 2 * M_PI, d.v0 = 0, d.v1 = 2 * M_PI;
  d.periodicU = d.periodicV = true;
  return d;
}
Eigen::Matrix2d TorusMetric::g(double, double v) const {
  const double w = R_ + r_ * std::cos(v);
  return Eigen::Vector2d(w * w, r_ * r_).asDiagonal();
}
MetricJet TorusMetric::jet(double u, double v) const {
  const double w = R_ + r_ * std::cos(v), sv = std::sin(v);
  MetricJet j;
  j.g = g(u, v);
  j.gu.setZero(), j.guu.setZero(), j.guv.setZero(), j.gv.setZero(), j.gvv.setZero();
  j.gv(0, 0) = -2 * r_ * sv * w;
  j.gvv(0, 0) = -2 * r_ * std::cos(v) * w + 2 * r_ * r_ * sv * sv;
  return j;
}
double TorusMetric::gaussianCurvature(double, double v) const {
  return std::cos(v) / (r_ * (R_ + r_ * std::cos(v)));
}
Eigen::Vector3d TorusMetric::position(double u, double v) const {
  const double w = R_ + r_ * std::cos(v);
  return {w * std::cos(u), w * std::sin(u), r_ * std::sin(v)};
}

// =====================================================================================================================
// flat torus

FlatTorusMetric::FlatTorusMetric(double tauRe, double tauIm, double scale) : tauRe_(tauRe), tauIm_(tauIm), L_(scale) {
  require(std::isfinite(tauRe), "flat-torus", "tau_re must be finite");
  require(std::isfinite(tauIm) && tauIm > 0, "flat-torus", "tau_im must be finite and > 0, found " + fmt(tauIm));
  require(std::isfinite(scale) && scale > 0, "flat-torus", "scale must be finite and > 0, found " + fmt(scale));
  Eigen::Matrix2d J;
  J << L_, L_ * tauRe_, 0, L_ * tauIm_;
  g_ = J.transpose() * J;
}
std::string FlatTorusMetric::description() const {
  return "flat-torus tau_re=" + fmt(tauRe_) + " tau_im=" + fmt(tauIm_) + " scale=" + fmt(L_);
}
ChartDomain FlatTorusMetric::domain() const {
  ChartDomain d;
  d.periodicU = d.periodicV = true;
  return d;
}
MetricJet FlatTorusMetric::jet(double, double) const {
  MetricJet j;
  j.g = g_;
  j.gu.setZero(), j.gv.setZero(), j.guu.setZero(), j.guv.setZero(), j.gvv.setZero();
  return j;
}

// =====================================================================================================================
// spherical cap

SphericalCapMetric::SphericalCapMetric(double R, double alpha) : R_(R), alpha_(alpha) {
  require(std::isfinite(R) && R > 0, "spherical-cap", "radius R must be finite and > 0, found " + fmt(R));
  require(std::isfinite(alpha) && alpha > 0 && alpha < M_PI, "spherical-cap",
          "angular radius alpha must lie in (0, pi), found " + fmt(alpha));
}
std::string SphericalCapMetric::description() const {
  return "spherical-cap R=" + fmt(R_) + " alpha=" + fmt(alpha_);
}
ChartDomain SphericalCapMetric::domain() const {
  return diskChart(alpha_ * R_);
}
Eigen::Matrix2d SphericalCapMetric::g(double, double v) const {
  const double s = R_ * std::sin(v / R_);
  return Eigen::Vector2d(s * s, 1.0).asDiagonal();
}
Eigen::Vector3d SphericalCapMetric::position(double u, double v) const {
  const double t = v / R_;
  return R_ * Eigen::Vector3d(std::sin(t) * std::cos(u), std::sin(t) * std::sin(u), std::cos(t));
}
std::optional<double> SphericalCapMetric::geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  if (alpha_ > M_PI / 2) return std::nullopt;
  return R_ * angleBetween(position(a.x(), a.y()), position(b.x(), b.y()));
}

// =====================================================================================================================
// hyperbolic disk

HyperbolicDiskMetric::HyperbolicDiskMetric(double geodesicRadius) : r_(geodesicRadius) {
  require(std::isfinite(geodesicRadius) && geodesicRadius > 0 && geodesicRadius <= 30, "hyperbolic-disk",
          "geodesic radius must lie in (0, 30] (beyond, 1 - tanh(r/2) underflows), found " + fmt(geodesicRadius));
  rho1_ = std::tanh(r_ / 2);
}
std::string HyperbolicDiskMetric::description() const {
  return "hyperbolic-disk radius=" + fmt(r_);
}
ChartDomain HyperbolicDiskMetric::domain() const {
  return diskChart(rho1_);
}
Eigen::Matrix2d HyperbolicDiskMetric::g(double, double v) const {
  const double c = 2 / (1 - v * v);
  return Eigen::Vector2d(c * c * v * v, c * c).asDiagonal();
}
std::optional<double> HyperbolicDiskMetric::geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const ChartDomain d = domain();
  const Eigen::Vector3d p = referencePoint(d, a.x(), a.y()), q = referencePoint(d, b.x(), b.y());
  // acosh(1 + x) = log1p(x + √(x(x+2))) keeps relative accuracy for short edges (x ~ edge²).
  const double x = 2 * (p - q).squaredNorm() / ((1 - p.squaredNorm()) * (1 - q.squaredNorm()));
  return std::log1p(x + std::sqrt(x * (x + 2)));
}

// =====================================================================================================================
// parametric surfaces, graphs, Bézier patches

ParametricSurfaceMetric::ParametricSurfaceMetric(std::string name, std::string description, ChartDomain domain, Map map,
                                                 Map tangents)
    : name_(std::move(name)),
      description_(std::move(description)),
      domain_(domain),
      map_(std::move(map)),
      tangents_(std::move(tangents)) {}

Eigen::Matrix2d ParametricSurfaceMetric::g(double u, double v) const {
  const SurfaceJet s = tangents_ ? tangents_(u, v) : map_(u, v);
  Eigen::Matrix2d m;
  m << s.xu.dot(s.xu), s.xu.dot(s.xv), s.xu.dot(s.xv), s.xv.dot(s.xv);
  return m;
}

namespace {
std::pair<Eigen::Matrix2d, Eigen::Matrix2d> firstDerivatives(const SurfaceJet& s) {
  Eigen::Matrix2d gu, gv;
  const double Fu = s.xuu.dot(s.xv) + s.xu.dot(s.xuv), Fv = s.xuv.dot(s.xv) + s.xu.dot(s.xvv);
  gu << 2 * s.xuu.dot(s.xu), Fu, Fu, 2 * s.xuv.dot(s.xv);
  gv << 2 * s.xuv.dot(s.xu), Fv, Fv, 2 * s.xvv.dot(s.xv);
  return {gu, gv};
}
}  // namespace

MetricJet ParametricSurfaceMetric::jet(double u, double v) const {
  MetricJet j;
  j.g = g(u, v);
  std::tie(j.gu, j.gv) = firstDerivatives(map_(u, v));
  const double h = 2e-3 * std::min(domain_.u1 - domain_.u0, domain_.v1 - domain_.v0) / M_PI;
  j.guu = centralDifference([&](double t) { return firstDerivatives(map_(u + t, v)).first; }, h);
  j.guv = centralDifference([&](double t) { return firstDerivatives(map_(u, v + t)).first; }, h);
  j.gvv = centralDifference([&](double t) { return firstDerivatives(map_(u, v + t)).second; }, h);
  return j;
}

double ParametricSurfaceMetric::gaussianCurvature(double u, double v) const {
  const SurfaceJet s = map_(u, v);
  const Eigen::Vector3d n = s.xu.cross(s.xv);
  const double n2 = n.squaredNorm();
  // K = (LN − M²)/(EG − F²) with L = X_uu·n̂ etc.; EG − F² = |X_u × X_v|², so with the unnormalized n = X_u × X_v,
  // K = (L'N' − M'²)/|n|⁴.
  const double L = s.xuu.dot(n), M = s.xuv.dot(n), N = s.xvv.dot(n);
  return (L * N - M * M) / (n2 * n2);
}

std::unique_ptr<ParametricSurfaceMetric> makeFunctionGraph(std::string description, double x0, double x1, double y0,
                                                           double y1, std::function<HeightJet(double, double)> height) {
  ChartDomain d;
  d.u0 = x0, d.u1 = x1, d.v0 = y0, d.v1 = y1;
  auto map = [height](double x, double y) {
    const HeightJet f = height(x, y);
    SurfaceJet s;
    s.x = {x, y, f[0]};
    s.xu = {1, 0, f[1]};
    s.xv = {0, 1, f[2]};
    s.xuu = {0, 0, f[3]};
    s.xuv = {0, 0, f[4]};
    s.xvv = {0, 0, f[5]};
    return s;
  };
  return std::make_unique<ParametricSurfaceMetric>("graph", std::move(description), d, map);
}

SurfaceJet evaluateBezierPatch(const BezierControlNet& net, double u, double v) {
  // Cubic Bernstein polynomials and their first two derivatives.
  auto basis = [](double t, std::array<double, 4>& b, std::array<double, 4>& db, std::array<double, 4>& ddb) {
    const double s = 1 - t;
    b = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
    db = {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
    ddb = {6 * s, 18 * t - 12, 6 - 18 * t, 6 * t};
  };
  std::array<double, 4> bu, dbu, ddbu, bv, dbv, ddbv;
  basis(u, bu, dbu, ddbu);
  basis(v, bv, dbv, ddbv);
  SurfaceJet s;
  s.x.setZero(), s.xu.setZero(), s.xv.setZero(), s.xuu.setZero(), s.xuv.setZero(), s.xvv.setZero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d& p = net[i][j];
      s.x += bu[i] * bv[j] * p;
      s.xu += dbu[i] * bv[j] * p;
      s.xv += bu[i] * dbv[j] * p;
      s.xuu += ddbu[i] * bv[j] * p;
      s.xuv += dbu[i] * dbv[j] * p;
      s.xvv += bu[i] * ddbv[j] * p;
    }
  return s;
}

SurfaceJet evaluateBezierTangents(const BezierControlNet& net, double u, double v) {
  // The Bernstein values and first derivatives of evaluateBezierPatch, by the same expressions in the same order.
  auto basis = [](double t, std::array<double, 4>& b, std::array<double, 4>& db) {
    const double s = 1 - t;
    b = {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
    db = {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
  };
  std::array<double, 4> bu, dbu, bv, dbv;
  basis(u, bu, dbu);
  basis(v, bv, dbv);
  SurfaceJet s;
  s.x.setZero(), s.xu.setZero(), s.xv.setZero(), s.xuu.setZero(), s.xuv.setZero(), s.xvv.setZero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d& p = net[i][j];
      s.xu += dbu[i] * bv[j] * p;
      s.xv += bu[i] * dbv[j] * p;
    }
  return s;
}

std::unique_ptr<ParametricSurfaceMetric> makeBezierPatch(std::string description, const BezierControlNet& net) {
  ChartDomain d;  // [0,1]², no identification
  return std::make_unique<ParametricSurfaceMetric>(
      "bezier-patch", std::move(description), d, [net](double u, double v) { return evaluateBezierPatch(net, u, v); },
      [net](double u, double v) { return evaluateBezierTangents(net, u, v); });
}

}  // namespace conformesh::intrinsic
