// smooth_metric.h — a Riemannian metric g(u,v) over one chart: the 2×2 symmetric positive-definite matrix, its first
// and second partial derivatives (analytic where a family provides them, else fourth-order differences), the area
// element √det g and the Gaussian curvature K (analytic where known, else Brioschi's formula). Charts are rectangles,
// optionally periodic; polar charts have coordinate poles, which nothing downstream evaluates: discretization and
// quadrature go through the chart's pole-free reference surface (docs/metrics.md §1, "Poles").
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

namespace conformesh::intrinsic {

// === chart

// The shape the chart's identifications give the surface. Sphere: u ∈ [0,2π) periodic, v ∈ [0,π], poles at both ends
// (x = (sin v cos u, sin v sin u, cos v) on the unit sphere). Disk: u ∈ [0,2π) periodic, v ∈ [0,v1], pole at v = 0
// (x = (v cos u, v sin u) in the plane), boundary circle at v1. Torus: periodic in u and v. Cylinder: periodic in u
// only, two boundary circles. Rectangle: no identification, one boundary loop.
enum class ChartShape { Rectangle, Cylinder, Torus, Disk, Sphere };

struct ChartDomain {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  bool periodicU = false, periodicV = false;
  bool poleAtV0 = false, poleAtV1 = false;  // the edge v = v0 (v1) is one point; requires periodicU

  ChartShape shape() const;
  // Genus and number of boundary loops of the surface the chart describes.
  int genus() const { return shape() == ChartShape::Torus ? 1 : 0; }
  int boundaryLoops() const;
  int eulerCharacteristic() const { return 2 - 2 * genus() - boundaryLoops(); }
};
std::string toString(ChartShape s);  // "rectangle", "cylinder", "torus", "disk", "sphere"

// Pole-free reference surfaces of the polar charts: the unit sphere (ChartShape::Sphere) and the plane (Disk, with the
// z component 0). For other shapes the reference point is (u, v, 0).
Eigen::Vector3d referencePoint(const ChartDomain& d, double u, double v);
// Inverse of referencePoint; at a pole u = 0. The derivative of (u,v) along a reference-space velocity `dx` is written
// to `duv` when it is not null (undefined exactly at a pole, where callers never ask).
Eigen::Vector2d chartPoint(const ChartDomain& d, const Eigen::Vector3d& x,
                           const Eigen::Vector3d& dx = Eigen::Vector3d::Zero(), Eigen::Vector2d* duv = nullptr);

// === metric

// g and its partial derivatives at one point; index 0 is u, 1 is v.
struct MetricJet {
  Eigen::Matrix2d g, gu, gv, guu, guv, gvv;
};

class SmoothMetric {
 public:
  virtual ~SmoothMetric() = default;

  // The family name as the registry knows it ("kerr-newman") and a one-line description with parameter values.
  virtual std::string family() const = 0;
  virtual std::string description() const = 0;
  virtual ChartDomain domain() const = 0;

  // The metric matrix [[g_uu, g_uv], [g_uv, g_vv]] at a chart point. Families whose derivatives come from finite
  // differences must accept points a few 1e-3 chart widths outside the chart (all analytic families here do).
  virtual Eigen::Matrix2d g(double u, double v) const = 0;

  // Default: fourth-order central differences of g(), with the chart scale w = min(u1 − u0, v1 − v0)/π (1 for sphere
  // charts). Steps h1 = 1e-3·w (first derivatives: truncation ~ h1⁴·|g⁽⁵⁾|/30 ≈ 1e-13 for g varying on scale w,
  // round-off ~ ε/h1 ≈ 1e-13) and h2 = 2e-3·w (second derivatives: truncation ~ h2⁴·|g⁽⁶⁾|/90 ≈ 2e-13, round-off
  // ~ ε/h2² ≈ 3e-11). Metrics varying on scales much finer than w (narrow bumps) lose accuracy as (h/scale)⁴.
  virtual MetricJet jet(double u, double v) const;

  // Default: Brioschi's formula on jet(), and within 1e-3·w of a coordinate pole (where Brioschi divides by det g → 0)
  // its limit at the pole, interpolated (smooth_metric.cpp). Families override it with closed forms.
  virtual double gaussianCurvature(double u, double v) const;

  // √det g: the area of the surface is ∫∫ areaElement du dv over the chart.
  double areaElement(double u, double v) const;

  // An isometric embedding in R³ when the family has one (sphere, ellipsoid, torus, graphs, patches, cap).
  virtual bool hasEmbedding() const { return false; }
  virtual Eigen::Vector3d position(double u, double v) const;  // throws InputError when !hasEmbedding()

  // The exact geodesic distance between two chart points when the family knows it in closed form or through a
  // reference implementation (round sphere, ellipsoid via GeographicLib's GeodesicExact, spherical cap, hyperbolic
  // disk). Meant for nearby points (T0 edges); nullopt otherwise.
  virtual std::optional<double> geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
};

// Brioschi's formula for K from E = g_uu, F = g_uv, G = g_vv and their derivatives (do Carmo §4-3, exercise 2).
double brioschiCurvature(const MetricJet& j);

// The fourth-order finite-difference jet of any metric (what SmoothMetric::jet does by default), for families that
// override jet() with analytic first derivatives but want to compare, and for tests.
MetricJet finiteDifferenceJet(const SmoothMetric& m, double u, double v);

// Throws InputError naming `where` when g is not finite, not symmetric positive definite (E > 0, EG − F² > 0).
void checkPositiveDefinite(const Eigen::Matrix2d& g, const std::string& where);

}  // namespace conformesh::intrinsic
