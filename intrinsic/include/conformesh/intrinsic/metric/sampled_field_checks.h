// sampled_field_checks.h — the structural checks that catch the usual mistakes of handing a sampled field
// (sampled_field.h) over — a transposed grid, a sphere chart without `poles both`, g_uu and g_vv swapped on a sphere
// chart — each an InputError that names the mistake and the fix, in O(NU·NV). SampledMetric runs them before its
// per-sample checks; field_check.h reports on a field that passes. docs/metrics.md §4 "Checks" derives the criteria.
#pragma once

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

}  // namespace conformesh::intrinsic
