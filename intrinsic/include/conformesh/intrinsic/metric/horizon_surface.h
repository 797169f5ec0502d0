// horizon_surface.h — an apparent horizon as numerical relativity reports it: a Strahlkörper (a surface star-shaped
// about a centre, r(θ, φ) = Σ a_lm Y_lm(θ, φ) in real orthonormal spherical harmonics up to l_max) in a spatial
// 3-metric γ_ij (spatial_metric.h), and its induced 2-metric g = X*γ as a SmoothMetric on the sphere chart
// (u = φ, v = θ about the centre, the chart of the Kerr–Newman family). Conventions, JSON format and derivations:
// docs/horizons.md §2–§3.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/intrinsic/metric/spatial_metric.h"

namespace conformesh::intrinsic {

// The real orthonormal basis (∫ Y_lm Y_l'm' dΩ = δ_ll' δ_mm'), WITHOUT the Condon–Shortley phase:
//   Y_l0 = N_l0 P_l(cos θ),  Y_lm = √2 N_lm P_l^m(cos θ) cos(mφ),  Y_l,−m = √2 N_lm P_l^m(cos θ) sin(mφ)  (m > 0),
// N_lm = √((2l+1)/(4π) (l−m)!/(l+m)!), P_l^m(x) = (1−x²)^(m/2) d^m P_l/dx^m (no (−1)^m). Files may say their
// coefficients carry the phase (`condon-shortley`): then a_lm is multiplied by (−1)^m on reading.
// SpectreSpherepack: SpECTRE's ylm::Spherepack coefficients as documented in its SpherepackIterator,
//   f = ½ Σ_l P̄_l^0 a(0,l) + Σ_{m≥1} Σ_l P̄_l^m (a(m,l) cos mφ − b(m,l) sin mφ),
//   P̄_l^m = (−1)^m √((2l+1)(l−m)!/(2(l+m)!)) P_l^m (Jackson's P_l^m, with the phase) = √(2π) N_lm P_l^m (ours),
// given as [l, m, a(m,l)] for m ≥ 0 and [l, −m, b(m,l)] for the sine terms; so a_l0 = √(π/2) a(0,l),
// a_lm = √π a(m,l), a_l,−m = −√π b(m,l) (docs/horizons.md §2).
enum class YlmConvention { Orthonormal, OrthonormalCondonShortley, SpectreSpherepack };
// "orthonormal", "orthonormal-condon-shortley", "spectre-spherepack"
std::string toString(YlmConvention c);
YlmConvention parseYlmConvention(const std::string& name);  // InputError naming the value otherwise
// The factor that takes a coefficient of (l, m) in convention c to the orthonormal one.
double ylmConventionFactor(YlmConvention c, int m);

// Y_lm and its θ, φ derivatives for one (l, m) at one point (for tests and the fit).
struct YlmJet {
  double y, yt, yp, ytt, ytp, ypp;  // Y, ∂θY, ∂φY, ∂θθY, ∂θφY, ∂φφY
};
// Every Y_lm with l ≤ lMax at (θ, φ), indexed l² + l + m, by the fully normalized Legendre recursions
// (docs/horizons.md §2), derivatives in θ by differentiating the recursions (exact, no differences).
std::vector<YlmJet> realYlmJets(int lMax, double theta, double phi);

// A radius function's value and partial derivatives in θ and φ.
struct RadiusJet {
  double r, rt, rp, rtt, rtp, rpp;
};

class Strahlkorper {
 public:
  struct Term {
    int l, m;
    double a;
  };
  // Coefficients in the orthonormal convention above; a (l, m) given twice, |m| > l, l < 0 or a non-finite value is
  // an InputError. lMax is the largest l given (at least 0).
  Strahlkorper(const Eigen::Vector3d& center, const std::vector<Term>& terms);
  const Eigen::Vector3d& center() const { return c_; }
  int lMax() const { return lMax_; }
  double coefficient(int l, int m) const;  // 0 for l > lMax
  std::vector<Term> terms() const;         // the non-zero coefficients, by l then m
  RadiusJet radius(double theta, double phi) const;
  // The surface point c + r(θ, φ) (sin θ cos φ, sin θ sin φ, cos θ).
  Eigen::Vector3d point(double theta, double phi) const;

 private:
  Eigen::Vector3d c_;
  int lMax_ = 0, mMax_ = 0;  // the largest l given, the largest |m| with a non-zero coefficient
  std::vector<double> a_;  // index l² + l + m
};

// Reads a Strahlkörper from JSON: {"center": [x, y, z], "coefficients": [[l, m, a_lm], ...], optional
// "convention": "orthonormal" (default) | "orthonormal-condon-shortley" | "spectre-spherepack"}. Throws InputError naming `source` and the
// key or the coefficient's index (expected vs found), and when the radius is not positive on the check grid
// (docs/horizons.md §2).
Strahlkorper parseStrahlkorperJson(const std::string& text, const std::string& source);
Strahlkorper readStrahlkorperJson(const std::string& path);
// InputError naming `source` when the radius is not positive on the (2 lMax + 8) × (4 lMax + 16) Gauss–Legendre ×
// uniform check grid (a sampling check, not a proof; docs/horizons.md §2).
void checkPositiveRadius(const Strahlkorper& s, const std::string& source);
// The JSON form (orthonormal convention, 17 significant digits).
std::string strahlkorperToJson(const Strahlkorper& s);

// The quadrature projection a_lm = ∫ r Y_lm dΩ of a radius function onto l ≤ lMax: Gauss–Legendre in cos θ with
// (lMax + 1)·oversample nodes, the trapezoidal rule in φ with (2 lMax + 2)·oversample nodes — exact for r
// band-limited to l ≤ (2·oversample − 1)(lMax + 1) − 1. Coefficients below 1e-15 · |a_00| are dropped.
Strahlkorper fitStrahlkorper(const std::function<double(double theta, double phi)>& r, int lMax,
                             const Eigen::Vector3d& center, int oversample = 2);

// The induced metric of a Strahlkörper in a spatial metric: X(φ, θ) = c + r n, g_ab = X_a · γ(X) X_b with u = φ,
// v = θ; first derivatives analytic (g_ab,c = X_ac·γX_b + X_a·γX_bc + X_a·(X_c^k ∂_kγ)X_b), second by fourth-order
// differences of the analytic first ones (step 2e-3), K by Brioschi (SmoothMetric's default with its pole limit).
class HorizonSurfaceMetric : public SmoothMetric {
 public:
  // Throws InputError when r ≤ 0 or g is not positive definite at a check-grid point (naming it).
  HorizonSurfaceMetric(Strahlkorper shape, std::shared_ptr<const SpatialMetric> gamma);
  std::string family() const override { return "horizon"; }
  std::string description() const override;
  ChartDomain domain() const override;
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;
  const Strahlkorper& shape() const { return shape_; }
  const SpatialMetric& spatialMetric() const { return *gamma_; }

 private:
  struct FirstJet {
    Eigen::Matrix2d g, gu, gv;
  };
  FirstJet firstJet(double u, double v) const;
  Strahlkorper shape_;
  std::shared_ptr<const SpatialMetric> gamma_;
};

// What the CLI builds from `--horizon SHAPE` (any form of strahlkorper_io.h's readHorizonShape) --spatial-metric NAME --param k=v ...`: the shape read from the file,
// the spatial metric by name (makeSpatialMetric). Throws InputError as those do.
std::unique_ptr<HorizonSurfaceMetric> makeHorizonMetric(const std::string& shapePath, const std::string& spatialMetric,
                                                        const std::map<std::string, double>& params);

// A shape file that also says what it lives in, for a time series (`conformesh sweep` with horizon inputs): optional
// keys "spatial_metric" (a name of makeSpatialMetric or an HDF5 grid FILE.h5[:/group], relative to the shape file's
// folder; default "kerr-schild"), "params" ({"M": 1, "a": 0.8, ...}, default {}) and "time" (a number, default none).
// Throws InputError naming the file and the key.
struct HorizonFileMetadata {
  std::string spatialMetric = "kerr-schild";
  std::map<std::string, double> params;
  bool hasTime = false;
  double time = 0;
};
HorizonFileMetadata readHorizonMetadata(const std::string& shapePath);
// makeHorizonMetric with the file's own spatial metric and parameters.
std::unique_ptr<HorizonSurfaceMetric> makeHorizonMetricFromFile(const std::string& shapePath);

}  // namespace conformesh::intrinsic
