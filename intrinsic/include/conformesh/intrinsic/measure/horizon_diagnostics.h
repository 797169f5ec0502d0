// horizon_diagnostics.h — the quasi-local figures physicists read off an apparent horizon, computed from its
// intrinsic 2-metric alone (no embedding): area A, irreducible mass √(A/16π), the circumferences of the chart's
// equator θ = π/2 and of its polar great circles (meridian φ₀ through both poles and back along φ₀ + π), and the
// dimensionless spin χ = a/M obtained by inverting Kerr's polar-to-equatorial circumference ratio (exact for Kerr).
// The curves are measured on the SMOOTH metric (periodic trapezoidal rule: spectral for a smooth metric), not on a
// triangulation. Derivation of the Kerr relation: docs/horizons.md §4. The rotation axis and the orbits of an
// approximate Killing vector, from a triangulation's edge lengths alone, are in killing_vector.h (§4d).
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

struct HorizonDiagnosticsOptions {
  int curvePoints = 512;  // trapezoidal nodes per closed curve
  int meridians = 8;      // polar great circles φ₀ = kπ/meridians, k = 0..meridians−1; the polar figure is their max
  // Relative tolerance of the adaptive area quadrature. A metric that is only C¹ (an interpolated γ,
  // sampled_spatial_metric.h) needs ~3·10⁶ evaluations for 1e-10; 1e-8 takes a tenth of that.
  double areaTolerance = 1e-10;
  std::string validate() const;  // "" when valid: curvePoints >= 16, meridians >= 1, areaTolerance in [1e-14, 1e-2]
};

struct HorizonDiagnostics {
  double area = 0;                     // ∫ √det g du dv (adaptive quadrature, metricArea, areaTolerance)
  double irreducibleMass = 0;          // √(A / 16π)
  double equatorialCircumference = 0;  // length of θ = π/2
  double polarCircumference = 0;       // the longest of the polar great circles sampled
  double minPolarCircumference = 0;    // the shortest of them (equal to the longest for an axisymmetric horizon)
  double circumferenceRatio = 0;       // polar / equatorial
  // χ with kerrCircumferenceRatio(χ) = ratio; NaN when the ratio lies outside Kerr's range [0.6080, 1] (not Kerr-like:
  // e.g. prolate, ratio > 1).
  double spin = 0;
};

// Throws InputError when the chart is not a sphere chart (u = φ periodic, v = θ with poles) or the options are invalid.
HorizonDiagnostics horizonDiagnostics(const SmoothMetric& metric, const HorizonDiagnosticsOptions& options = {});

// Kerr's C_polar / C_equatorial as a function of χ = a/M ∈ [0, 1]: √(2 r₊) E(χ²/(2 r₊)) / π with r₊ = 1 + √(1 − χ²)
// (M = 1) and E(m) the complete elliptic integral of the second kind with parameter m. 1 at χ = 0, 0.6080 at χ = 1.
double kerrCircumferenceRatio(double chi);
// The inverse by bisection to 1e-15 (the ratio is strictly decreasing); NaN outside [kerrCircumferenceRatio(1), 1].
double spinFromCircumferenceRatio(double ratio);

}  // namespace conformesh::intrinsic
