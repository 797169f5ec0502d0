// field_check.h — does a sampled field (sampled_field.h) describe what it claims? The structural checks that catch the
// usual mistakes of handing a field over — a transposed grid, a sphere chart without `poles both`, g_uu and g_vv
// swapped on a sphere chart — each an InputError that names the mistake and the fix, in O(NU·NV); and the report of
// `conformesh field check` (topology, area, ∫K dA, smallest det g). docs/metrics.md §4 "Checks" derives the criteria.
// Depends on sampled_field.h, sampled_metric.h and metric_quadrature.h.
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/sampled_field.h"

namespace conformesh::intrinsic {

// Throws InputError "SOURCE: the samples look transposed ..." when the data, read u fastest as the format says, is
// more than kTransposedRoughness times rougher (mean squared second difference along both axes, summed over the three
// components) than the same numbers read v fastest. A smooth field read in the wrong order jumps every NV samples;
// read in the right order its second differences are O(h²). Square grids (NU = NV) are not tested: both readings are
// grids of the same shape.
constexpr double kTransposedRoughness = 100;
void checkFieldGridOrder(const SampledField& field);

// Sphere charts. Without poles (periodic u, non-periodic v): throws "is this a sphere? add `poles both`" when the
// circle v = const at an end row is shorter than its change to the next row (2·C_end < C_next, C_j = Σ_i √g_uu Δu):
// the circles would shrink to a point within one grid step beyond the chart. With `poles both`: the regular form
// (g_uu/sin²v, g_uv/sin v, g_vv) at each pole, estimated at each u as the mean of the nearest row's samples at u and
// u + π (error O(h²)), must be finite and positive definite; its trace g_uu/sin²v + g_vv must be constant along u
// within ±kPoleVariationBound of its mean (at a smooth pole with Cartesian metric G the regular form is
// (t·Gt, n·Gt, n·Gn), t and n the unit vectors along and across the meridian, so the trace is tr G at every u) — else
// the error asks whether the grid is transposed; and its mean g_uu/sin²v and mean g_vv over u must agree within a
// factor kPoleRatioBound (both are tr G / 2) — else the error says that u must be φ and v θ (the mistake of listing θθ
// first). The bounds are far above the O(h²) error of the estimate: they catch gross mistakes, not cone points.
constexpr double kPoleVariationBound = 0.5;
constexpr double kPoleRatioBound = 2;
void checkFieldPoles(const SampledField& field);

// What `conformesh field check FILE` prints. Area and ∫K dA by metricArea / metricTotalCurvature of the spline
// interpolant (SampledMetric) with the default quadrature tolerances.
struct FieldCheckReport {
  std::string source, shape;  // shape: toString(ChartShape): "sphere", "torus", "cylinder", "rectangle"
  int nu = 0, nv = 0;
  int genus = 0, boundaryLoops = 0, eulerCharacteristic = 0;
  double area = 0, areaError = 0;                        // quadrature's error estimate
  double totalCurvature = 0, totalCurvatureError = 0;    // ∫K dA
  double gaussBonnet = 0;                                // 2πχ, the closed surfaces' ∫K dA (NaN with boundary)
  double minDetG = 0;                                    // smallest det g over the samples
  int minDetNodeU = 0, minDetNodeV = 0, minDetLine = 0;  // its grid node and source line (0: no line)
  double minDetRegular = 0;  // pole-to-pole fields: smallest det of the regular form, det g / sin²v (else NaN)
};
// Runs every check (checkFieldGridOrder, checkFieldPoles, the samples' positive-definiteness) — throws their
// InputError — and measures the report.
FieldCheckReport checkField(const SampledField& field);

}  // namespace conformesh::intrinsic
