// spatial_metric.h — Riemannian 3-metrics γ_ij(x) on (a region of) R³ in Cartesian coordinates, the spatial slices
// numerical relativity writes its horizons in: flat space, Schwarzschild in isotropic coordinates and Kerr in
// Kerr–Schild Cartesian coordinates, each with analytic first derivatives ∂_k γ_ij. A horizon surface
// (horizon_surface.h) pulls γ back to its 2-metric. Formulas and derivative derivations: docs/horizons.md §1.
#pragma once

#include <array>
#include <memory>
#include <string>

#include <Eigen/Core>

namespace conformesh::intrinsic {

// γ_ij at a point and its first partial derivatives: d[k](i,j) = ∂γ_ij/∂x^k.
struct SpatialMetricJet {
  Eigen::Matrix3d g;
  std::array<Eigen::Matrix3d, 3> d;
};

class SpatialMetric {
 public:
  virtual ~SpatialMetric() = default;
  virtual std::string name() const = 0;         // "kerr-schild", "schwarzschild-isotropic", "flat"
  virtual std::string description() const = 0;  // name with parameter values
  // γ_ij at Cartesian x. Throws InputError at a coordinate singularity (the Kerr ring, the isotropic puncture).
  virtual Eigen::Matrix3d gamma(const Eigen::Vector3d& x) const = 0;
  // γ_ij and ∂_k γ_ij at x, analytic.
  virtual SpatialMetricJet jet(const Eigen::Vector3d& x) const = 0;
};

// δ_ij.
class FlatSpatialMetric : public SpatialMetric {
 public:
  std::string name() const override { return "flat"; }
  std::string description() const override { return "flat"; }
  Eigen::Matrix3d gamma(const Eigen::Vector3d&) const override { return Eigen::Matrix3d::Identity(); }
  SpatialMetricJet jet(const Eigen::Vector3d& x) const override;
};

// Schwarzschild of mass M in isotropic coordinates about `center` c: γ_ij = ψ⁴ δ_ij, ψ = 1 + M/(2ρ), ρ = |x − c|.
// The horizon is the sphere ρ = M/2, of area 16πM². Throws InputError at ρ = 0 (the puncture).
class IsotropicSchwarzschildMetric : public SpatialMetric {
 public:
  IsotropicSchwarzschildMetric(double M, const Eigen::Vector3d& center);
  std::string name() const override { return "schwarzschild-isotropic"; }
  std::string description() const override;
  Eigen::Matrix3d gamma(const Eigen::Vector3d& x) const override;
  SpatialMetricJet jet(const Eigen::Vector3d& x) const override;

 private:
  double M_;
  Eigen::Vector3d c_;
};

// Kerr of mass M and spin a (angular momentum aM along +z, |a| ≤ M) in Kerr–Schild Cartesian coordinates about
// `center` c (y = x − c): γ_ij = δ_ij + 2H l_i l_j with H = M r³/(r⁴ + a² z²) and
// l = ((r y₁ + a y₂)/(r² + a²), (r y₂ − a y₁)/(r² + a²), y₃/r), where r is the Boyer–Lindquist-like radius,
// (y₁² + y₂²)/(r² + a²) + y₃²/r² = 1. The horizon r = r₊ = M + √(M² − a²) is the coordinate spheroid with
// semi-axes √(r₊² + a²) (equatorial) and r₊ (polar); its induced metric is Smarr's, area 8πMr₊.
// Throws InputError on the ring singularity r = 0, y₃ = 0.
class KerrSchildMetric : public SpatialMetric {
 public:
  KerrSchildMetric(double M, double a, const Eigen::Vector3d& center);
  std::string name() const override { return "kerr-schild"; }
  std::string description() const override;
  Eigen::Matrix3d gamma(const Eigen::Vector3d& x) const override;
  SpatialMetricJet jet(const Eigen::Vector3d& x) const override;
  double horizonRadius() const;  // r₊
  // The Kerr–Schild radius r at x (the positive root of r⁴ − (|y|² − a²) r² − a² y₃² = 0).
  double radius(const Eigen::Vector3d& x) const;

 private:
  double M_, a_;
  Eigen::Vector3d c_;
};

// The registry by name (makeSpatialMetric, spatialMetricList), including sampled grids: spatial_metric_registry.h.

}  // namespace conformesh::intrinsic
