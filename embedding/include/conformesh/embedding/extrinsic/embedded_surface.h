// embedded_surface.h — the extrinsic geometry of a SmoothMetric's own embedding (SmoothMetric::position), read off at
// points of the chart's pole-free reference surface: position, tangent vectors, unit normal and the mean curvature,
// by central differences of position() (no family needs to supply second derivatives).
//
// Working on the reference surface (unit sphere for sphere charts, the plane (u, v, 0) or the disk plane otherwise;
// smooth_metric.h) rather than in (u, v) keeps poles harmless: the map y ↦ position(chartPoint(y)) is smooth across
// them, and chartPoint only looks at y's direction on sphere charts, so a chord point y = Σ bᵢ xᵢ of a reference
// triangle is its gnomonic (geodesic-triangle) image — the natural parametrization η of the paper's §4.4 / §5.1.2.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::embedding {

// The surface map X(a, b) = position(y + a·e₁ + b·e₂) near a = b = 0 and what its derivatives give.
struct LocalSurfaceJet {
  Eigen::Vector3d position, xa, xb;  // X and its first partials
  Eigen::Vector3d normal;            // (X_a × X_b)/|X_a × X_b|
  double areaFactor = 0;             // |X_a × X_b|: dA = areaFactor da db
  // κ₁ + κ₂ = −(E N − 2F M + G L)/(E G − F²) with L, M, N = n·X_aa, n·X_ab, n·X_bb: positive where the surface bends
  // away from `normal` (a sphere of radius R with outward normal: 2/R). This sum, not the average (κ₁ + κ₂)/2, is
  // what the edge sums Σ |e ∩ B| β(e) of paper eq. 2 converge to (a prism of n sides around a cylinder of radius R and
  // length ℓ has Σ |e| β(e) = 2πℓ = ∫ (κ₁ + κ₂) dA).
  double meanCurvature = 0;
};

class EmbeddedSurface {
 public:
  // Throws InputError naming the family when metric.hasEmbedding() is false. Keeps a reference to `metric`.
  explicit EmbeddedSurface(const intrinsic::SmoothMetric& metric);

  const intrinsic::SmoothMetric& metric() const { return metric_; }
  const intrinsic::ChartDomain& domain() const { return domain_; }
  bool sphereChart() const { return sphere_; }

  // position(chartPoint(y)); y need not lie on the reference surface for sphere charts (only its direction counts).
  Eigen::Vector3d position(const Eigen::Vector3d& y) const;
  // y brought back onto the reference surface (normalized on sphere charts, z = 0 otherwise).
  Eigen::Vector3d retract(const Eigen::Vector3d& y) const;
  // Two orthonormal tangent vectors of the reference surface at y, with t₁ × t₂ the outward normal (sphere) or +z.
  void referenceFrame(const Eigen::Vector3d& y, Eigen::Vector3d& t1, Eigen::Vector3d& t2) const;

  // Derivatives of X(a, b) = position(y + a e₁ + b e₂) by second-order central differences with a reference-space
  // step h: with `curvature`, h = 2e-4·w (w = 1 on sphere charts, else min(u₁ − u₀, v₁ − v₀)/π), 9 evaluations, ≈ 1e-8
  // relative; without, first derivatives only, h = 1e-5·w, 5 evaluations, ≈ 1e-10. docs/embedding.md derives the steps.
  LocalSurfaceJet jet(const Eigen::Vector3d& y, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                      bool curvature = true) const;

 private:
  const intrinsic::SmoothMetric& metric_;
  intrinsic::ChartDomain domain_;
  bool sphere_ = false;
  double width_ = 1;
};

}  // namespace conformesh::embedding
