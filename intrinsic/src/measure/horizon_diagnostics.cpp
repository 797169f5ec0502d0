// horizon_diagnostics.cpp — area, irreducible mass, circumferences and the circumference-ratio spin
// (horizon_diagnostics.h; docs/horizons.md §4).
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"

#include <cmath>
#include <limits>

#include <boost/math/special_functions/ellint_2.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::intrinsic {

namespace {

// Length of the equator v = π/2 by the periodic trapezoidal rule on √g_uu.
double equatorLength(const SmoothMetric& m, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) sum += std::sqrt(m.g(2 * M_PI * (k + 0.5) / n, M_PI / 2)(0, 0));
  return sum * 2 * M_PI / n;
}

// Length of the great circle through both poles made of the meridians φ₀ and φ₀ + π, parametrized by t ∈ [0, 2π):
// θ = t on the first half, θ = 2π − t on the second (|dθ/dt| = 1), so the speed is √g_vv; the curve is smooth through
// the poles, so the periodic trapezoidal rule converges spectrally. Nodes at half steps avoid the poles themselves.
double meridianLength(const SmoothMetric& m, double phi0, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * (k + 0.5) / n;
    const double u = t < M_PI ? phi0 : phi0 + M_PI, v = t < M_PI ? t : 2 * M_PI - t;
    sum += std::sqrt(m.g(std::fmod(u, 2 * M_PI), v)(1, 1));
  }
  return sum * 2 * M_PI / n;
}

}  // namespace

std::string HorizonDiagnosticsOptions::validate() const {
  if (curvePoints < 16) return "horizon diagnostics: curvePoints must be >= 16, found " + std::to_string(curvePoints);
  if (meridians < 1) return "horizon diagnostics: meridians must be >= 1, found " + std::to_string(meridians);
  if (!(areaTolerance >= 1e-14 && areaTolerance <= 1e-2))
    return "horizon diagnostics: areaTolerance must lie in [1e-14, 1e-2], found " + std::to_string(areaTolerance);
  return "";
}

double kerrCircumferenceRatio(double chi) {
  const double rp = 1 + std::sqrt(std::max(0.0, 1 - chi * chi));
  const double m = chi * chi / (2 * rp);
  // Boost's ellint_2 takes the modulus k = √m.
  return std::sqrt(2 * rp) * boost::math::ellint_2(std::sqrt(m)) / M_PI;
}

double spinFromCircumferenceRatio(double ratio) {
  const double lo = kerrCircumferenceRatio(1.0);
  if (!(ratio >= lo * (1 - 1e-14) && ratio <= 1 + 1e-14)) return std::numeric_limits<double>::quiet_NaN();
  double a = 0, b = 1;  // ratio(a) ≥ ratio ≥ ratio(b)
  while (b - a > 1e-15) {
    const double c = 0.5 * (a + b);
    (kerrCircumferenceRatio(c) > ratio ? a : b) = c;
  }
  return 0.5 * (a + b);
}

HorizonDiagnostics horizonDiagnostics(const SmoothMetric& metric, const HorizonDiagnosticsOptions& options) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError(e);
  if (metric.domain().shape() != ChartShape::Sphere)
    throw InputError("horizon diagnostics need a sphere chart (u = phi, v = theta), found a " +
                     toString(metric.domain().shape()) + " chart for " + metric.description());
  HorizonDiagnostics d;
  QuadratureOptions q;
  q.relativeTolerance = options.areaTolerance;
  q.absoluteTolerance = 0;
  d.area = metricArea(metric, q).value;
  d.irreducibleMass = std::sqrt(d.area / (16 * M_PI));
  d.equatorialCircumference = equatorLength(metric, options.curvePoints);
  d.polarCircumference = 0, d.minPolarCircumference = std::numeric_limits<double>::infinity();
  for (int k = 0; k < options.meridians; ++k) {
    const double c = meridianLength(metric, M_PI * k / options.meridians, options.curvePoints);
    d.polarCircumference = std::max(d.polarCircumference, c);
    d.minPolarCircumference = std::min(d.minPolarCircumference, c);
  }
  d.circumferenceRatio = d.polarCircumference / d.equatorialCircumference;
  d.spin = spinFromCircumferenceRatio(d.circumferenceRatio);
  return d;
}

}  // namespace conformesh::intrinsic
