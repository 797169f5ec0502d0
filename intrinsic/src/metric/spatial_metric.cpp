// spatial_metric.cpp — the analytic 3-metrics of spatial_metric.h; derivatives derived in docs/horizons.md §1.
#include "conformesh/intrinsic/metric/spatial_metric.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "metric/family_checks.h"

namespace conformesh::intrinsic {

namespace {

using metric_detail::fmt;
using metric_detail::require;

std::string centerText(const Eigen::Vector3d& c) {
  return c.isZero() ? "" : " center=(" + fmt(c.x()) + "," + fmt(c.y()) + "," + fmt(c.z()) + ")";
}

}  // namespace

SpatialMetricJet FlatSpatialMetric::jet(const Eigen::Vector3d&) const {
  SpatialMetricJet j;
  j.g.setIdentity();
  for (auto& d : j.d) d.setZero();
  return j;
}

// ---------------------------------------------------------------------------------------------------------------------
// Schwarzschild, isotropic

IsotropicSchwarzschildMetric::IsotropicSchwarzschildMetric(double M, const Eigen::Vector3d& center)
    : M_(M), c_(center) {
  require(std::isfinite(M) && M > 0, "schwarzschild-isotropic", "mass M must be finite and > 0, found " + fmt(M));
  require(center.allFinite(), "schwarzschild-isotropic", "the center must be finite");
}
std::string IsotropicSchwarzschildMetric::description() const {
  return "schwarzschild-isotropic M=" + fmt(M_) + centerText(c_);
}
Eigen::Matrix3d IsotropicSchwarzschildMetric::gamma(const Eigen::Vector3d& x) const {
  return jet(x).g;
}
SpatialMetricJet IsotropicSchwarzschildMetric::jet(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d y = x - c_;
  const double rho = y.norm();
  if (!(rho > 0)) throw InputError("spatial metric schwarzschild-isotropic: evaluated at the puncture " + fmt(x.x()) +
                                   "," + fmt(x.y()) + "," + fmt(x.z()));
  const double psi = 1 + M_ / (2 * rho);
  SpatialMetricJet j;
  j.g = std::pow(psi, 4) * Eigen::Matrix3d::Identity();
  // ∂_k ψ⁴ = 4ψ³ ∂_k ψ, ∂_k ψ = −M y_k / (2ρ³).
  for (int k = 0; k < 3; ++k) j.d[k] = 4 * psi * psi * psi * (-M_ * y[k] / (2 * rho * rho * rho)) *
                                       Eigen::Matrix3d::Identity();
  return j;
}

// ---------------------------------------------------------------------------------------------------------------------
// Kerr–Schild

KerrSchildMetric::KerrSchildMetric(double M, double a, const Eigen::Vector3d& center) : M_(M), a_(a), c_(center) {
  require(std::isfinite(M) && M > 0, "kerr-schild", "mass M must be finite and > 0, found " + fmt(M));
  require(std::isfinite(a) && std::abs(a) <= M * (1 + 1e-14), "kerr-schild",
          "spin a must satisfy |a| <= M (no horizon otherwise), found a=" + fmt(a) + " M=" + fmt(M));
  require(center.allFinite(), "kerr-schild", "the center must be finite");
}
std::string KerrSchildMetric::description() const {
  return "kerr-schild M=" + fmt(M_) + " a=" + fmt(a_) + centerText(c_);
}
double KerrSchildMetric::horizonRadius() const {
  return M_ + std::sqrt(std::max(0.0, M_ * M_ - a_ * a_));
}
double KerrSchildMetric::radius(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d y = x - c_;
  const double a2 = a_ * a_, b = 0.5 * (y.squaredNorm() - a2);
  // r² = b + √(b² + a² z²); for b < 0 the equivalent a² z² / (√(b² + a²z²) − b) avoids cancellation.
  const double s = std::sqrt(b * b + a2 * y.z() * y.z());
  const double r2 = b >= 0 ? b + s : a2 * y.z() * y.z() / (s - b);
  return std::sqrt(r2);
}
Eigen::Matrix3d KerrSchildMetric::gamma(const Eigen::Vector3d& x) const {
  return jet(x).g;
}
SpatialMetricJet KerrSchildMetric::jet(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d y = x - c_;
  const double r = radius(x), a = a_, a2 = a * a, z = y.z();
  if (!(r > 0)) throw InputError("spatial metric kerr-schild: evaluated on the ring singularity at " + fmt(x.x()) +
                                 "," + fmt(x.y()) + "," + fmt(x.z()));
  const double r2 = r * r, q = r2 + a2, den = r2 * r2 + a2 * z * z;
  // ∂_k r from r⁴ − (|y|² − a²) r² − a² z² = 0: ∂_k r = (r² y_k + a² z δ_kz) / (r (2r² − |y|² + a²)).
  const double dr0 = r * (2 * r2 - y.squaredNorm() + a2);
  Eigen::Vector3d dr = r2 * y / dr0;
  dr.z() += a2 * z / dr0;
  const double H = M_ * r2 * r / den;
  const Eigen::Vector3d l((r * y.x() + a * y.y()) / q, (r * y.y() - a * y.x()) / q, z / r);
  Eigen::Vector3d dH;
  Eigen::Matrix3d dl;  // dl(i, k) = ∂_k l_i
  for (int k = 0; k < 3; ++k) {
    const double dz = k == 2 ? 1 : 0;
    dH[k] = M_ * (3 * r2 * dr[k] * den - r2 * r * (4 * r2 * r * dr[k] + 2 * a2 * z * dz)) / (den * den);
    const double dq = 2 * r * dr[k];
    dl(0, k) = (dr[k] * y.x() + r * (k == 0) + a * (k == 1)) / q - (r * y.x() + a * y.y()) * dq / (q * q);
    dl(1, k) = (dr[k] * y.y() + r * (k == 1) - a * (k == 0)) / q - (r * y.y() - a * y.x()) * dq / (q * q);
    dl(2, k) = dz / r - z * dr[k] / r2;
  }
  SpatialMetricJet j;
  j.g = Eigen::Matrix3d::Identity() + 2 * H * l * l.transpose();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d lk = dl.col(k);
    j.d[k] = 2 * dH[k] * l * l.transpose() + 2 * H * (lk * l.transpose() + l * lk.transpose());
  }
  return j;
}

}  // namespace conformesh::intrinsic
