// metric_families.h — the built-in Riemannian metrics, each with its chart, closed-form curvature and (where it has
// one) its embedding and exact geodesic distance. metric_registry.h builds them by name from `key=value` parameters.
//
// Families: round sphere; ellipsoid of revolution (GeographicLib); torus of revolution; the Kerr–Newman horizon (Smarr
// 1973); flat tori of any lattice; spherical cap; hyperbolic (Poincaré) disk; function graphs z = f(x,y); pull-backs of
// parametric surfaces and bicubic Bézier patches. For genus ≥ 2 there is no single-chart family here: a smooth closed
// surface of genus ≥ 2 needs several charts (or a Fuchsian group), which SmoothMetric does not model; such surfaces
// enter conformesh as triangulations with edge lengths. docs/metrics.md gives every formula.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace GeographicLib {
class GeodesicExact;
}

namespace conformesh::intrinsic {

// =====================================================================================================================
// surfaces of revolution with poles: ds² = E(θ) dθ² + G(θ) dφ², chart u = φ ∈ [0,2π), v = θ ∈ [0,π]

class RoundSphereMetric : public SmoothMetric {
 public:
  explicit RoundSphereMetric(double radius);
  std::string family() const override { return "sphere"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;
  double gaussianCurvature(double, double) const override { return 1 / (R_ * R_); }
  bool hasEmbedding() const override { return true; }
  Eigen::Vector3d position(double u, double v) const override;
  std::optional<double> geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const override;
  double radius() const { return R_; }

 private:
  double R_;
};

// Ellipsoid of revolution with equatorial radius a and flattening f (f < 0: prolate; |f| up to 0.99, the range of
// GeographicLib's GeodesicExact). The chart is u = longitude λ, v = θ = π/2 − χ with χ the CONFORMAL latitude, so the
// chart is the exact conformal map to the unit sphere: ds² = m(θ)² (dθ² + sin²θ dλ²) with m = ν cos φ / cos χ. The
// geographic latitude φ is recovered from χ by Newton's method on GeographicLib's Math::taupf (Karney 2011, eq. 7–9).
class EllipsoidMetric : public SmoothMetric {
 public:
  EllipsoidMetric(double a, double f);
  std::string family() const override { return "ellipsoid"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  double gaussianCurvature(double u, double v) const override;  // (1 − e² sin²φ)² / (a² (1 − e²)) = 1/(ρ ν)
  bool hasEmbedding() const override { return true; }
  Eigen::Vector3d position(double u, double v) const override;
  // GeographicLib::GeodesicExact::Inverse between the two points' geographic coordinates.
  std::optional<double> geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const override;

  // GeodesicExact's inverse problem between two chart points: distance s12 and the forward azimuths at both ends
  // (radians, clockwise from north, as GeographicLib defines them).
  struct GeodesicInverse {
    double distance, azimuth1, azimuth2;
  };
  GeodesicInverse geodesicInverse(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // Azimuth (clockwise from north) of the chart direction (du, dv) at colatitude θ: the chart is conformal, so it is
  // atan2(sin θ du, −dv) — east is +u, north is −v.
  static double chartAzimuth(double theta, double du, double dv) { return std::atan2(std::sin(theta) * du, -dv); }

  double equatorialRadius() const { return a_; }
  double flattening() const { return f_; }
  // Geographic latitude φ (radians) of conformal colatitude θ, and the inverse.
  double geographicLatitude(double theta) const;
  double conformalColatitude(double phi) const;
  // The conformal scale factor m(θ) = |ds| / |ds on the unit sphere|. What g() evaluates (every output edge's length
  // calls it at 15+ points), so its Newton iteration starts from the sine series below: one step then reaches
  // round-off where three or four from GeographicLib's own guess did.
  double conformalScale(double theta) const;
  // Closed-form area: 2πa² (1 + (1 − e²) atanh(e)/e) (oblate; = 2πa² + πb²/e·ln((1+e)/(1−e))), continued to
  // prolate ellipsoids (e² < 0) as 2πa² (1 + (b/a)² atan(|e|)/|e|).
  double area() const;

 private:
  double a_, f_, e2_, es_;
  // φ − χ = Σ_k b_k sin 2kχ (b_1 first), fitted at construction to the exact inversion; empty where it fits badly.
  std::vector<double> latitudeSeries_;
  std::shared_ptr<const GeographicLib::GeodesicExact> geodesic_;
};

// The Kerr–Newman black-hole horizon of mass M, spin a (angular momentum aM) and charge Q, with the intrinsic metric of
// Smarr (Phys. Rev. D 7, 289, 1973): ds² = ρ² dθ² + (r₊² + a²)² sin²θ / ρ² dφ², ρ² = r₊² + a² cos²θ,
// r₊ = M + √(M² − a² − Q²). Valid for every a² + Q² ≤ M² (extremal included). K = (r₊²+a²)(r₊² − 3a²cos²θ)/ρ⁶, which
// is negative at the poles when a² > r₊²/3 (for Q = 0: a/M > √3/2), where no isometric embedding in R³ exists.
class KerrNewmanMetric : public SmoothMetric {
 public:
  KerrNewmanMetric(double M, double a, double Q);
  std::string family() const override { return "kerr-newman"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;
  double gaussianCurvature(double u, double v) const override;
  double horizonRadius() const { return rp_; }  // r₊
  double area() const;                          // 4π (r₊² + a²)
  double equatorialCircumference() const;       // 2π (r₊² + a²) / r₊

 private:
  double M_, a_, Q_, rp_;
};

// =====================================================================================================================
// other closed surfaces

// Torus of revolution, tube radius r about a circle of radius R > r: ds² = (R + r cos v)² du² + r² dv², u, v ∈ [0,2π).
// K = cos v / (r (R + r cos v)): positive outside (cos v > 0, ∫K⁺dA = 4π), negative inside (∫K⁻dA = −4π).
class TorusMetric : public SmoothMetric {
 public:
  TorusMetric(double R, double r);
  std::string family() const override { return "torus"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;
  double gaussianCurvature(double u, double v) const override;
  bool hasEmbedding() const override { return true; }
  Eigen::Vector3d position(double u, double v) const override;

 private:
  double R_, r_;
};

// Flat torus R²/(ω1 Z + ω2 Z) with ω1 = L (1, 0), ω2 = L (Re τ, Im τ), Im τ > 0; chart (u,v) ∈ [0,1)², the point
// u ω1 + v ω2, so g = Jᵀ J with J = [ω1 ω2] (constant). Straight chart segments are geodesics.
class FlatTorusMetric : public SmoothMetric {
 public:
  FlatTorusMetric(double tauRe, double tauIm, double scale);
  std::string family() const override { return "flat-torus"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double, double) const override { return g_; }
  MetricJet jet(double u, double v) const override;
  double gaussianCurvature(double, double) const override { return 0; }

 private:
  double tauRe_, tauIm_, L_;
  Eigen::Matrix2d g_;
};

// =====================================================================================================================
// disks (polar charts, pole at v = 0)

// Geodesic disk of angular radius α on the sphere of radius R, in geodesic polar coordinates: u = φ, v = r ∈ [0, αR],
// ds² = dr² + R² sin²(r/R) dφ². K = 1/R², area 2πR²(1 − cos α).
class SphericalCapMetric : public SmoothMetric {
 public:
  SphericalCapMetric(double R, double alpha);
  std::string family() const override { return "spherical-cap"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  double gaussianCurvature(double, double) const override { return 1 / (R_ * R_); }
  bool hasEmbedding() const override { return true; }
  Eigen::Vector3d position(double u, double v) const override;
  // R × the angle between the points (the intrinsic distance when α ≤ π/2, where the cap is convex); nullopt otherwise.
  std::optional<double> geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const override;

 private:
  double R_, alpha_;
};

// Hyperbolic disk of geodesic radius r in the Poincaré model: u = φ, v = ρ ∈ [0, tanh(r/2)] the Euclidean radius,
// ds² = 4 (dρ² + ρ² dφ²) / (1 − ρ²)². K = −1, area 4π sinh²(r/2).
class HyperbolicDiskMetric : public SmoothMetric {
 public:
  explicit HyperbolicDiskMetric(double geodesicRadius);
  std::string family() const override { return "hyperbolic-disk"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  double gaussianCurvature(double, double) const override { return -1; }
  // acosh(1 + 2|p − q|² / ((1 − |p|²)(1 − |q|²))).
  std::optional<double> geodesicDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const override;

 private:
  double r_, rho1_;
};

// =====================================================================================================================
// pull-backs of embedded surfaces

// A parametric surface X(u,v) with its first and second partial derivatives. g = JᵀJ with analytic first derivatives
// (g_ij,k = X_ik·X_j + X_i·X_jk); second derivatives of g by fourth-order differences of the analytic first ones;
// K = (LN − M²)/(EG − F²) from the second fundamental form (no third derivatives needed).
struct SurfaceJet {
  Eigen::Vector3d x, xu, xv, xuu, xuv, xvv;
};
class ParametricSurfaceMetric : public SmoothMetric {
 public:
  using Map = std::function<SurfaceJet(double u, double v)>;
  // `tangents`, when given, returns X_u and X_v (the other fields unused) equal bit for bit to map's: g() then
  // evaluates only what the first fundamental form needs (every output edge's length calls g at 15+ points).
  ParametricSurfaceMetric(std::string name, std::string description, ChartDomain domain, Map map, Map tangents = {});
  std::string family() const override { return name_; }
  std::string description() const override { return description_; }
  ChartDomain domain() const override { return domain_; }
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;
  double gaussianCurvature(double u, double v) const override;
  bool hasEmbedding() const override { return true; }
  Eigen::Vector3d position(double u, double v) const override { return map_(u, v).x; }

 private:
  std::string name_, description_;
  ChartDomain domain_;
  Map map_, tangents_;
};

// The graph z = f(x,y) over a rectangle; `height` returns {f, f_x, f_y, f_xx, f_xy, f_yy}.
using HeightJet = std::array<double, 6>;
std::unique_ptr<ParametricSurfaceMetric> makeFunctionGraph(std::string description, double x0, double x1, double y0,
                                                           double y1, std::function<HeightJet(double, double)> height);

// One bicubic Bézier patch over [0,1]², control points P[i][j] (i along u, j along v).
using BezierControlNet = std::array<std::array<Eigen::Vector3d, 4>, 4>;
SurfaceJet evaluateBezierPatch(const BezierControlNet& net, double u, double v);
// X_u and X_v only (x and the second derivatives left zero), bit for bit those of evaluateBezierPatch.
SurfaceJet evaluateBezierTangents(const BezierControlNet& net, double u, double v);
std::unique_ptr<ParametricSurfaceMetric> makeBezierPatch(std::string description, const BezierControlNet& net);

}  // namespace conformesh::intrinsic
