// field_check.h — the report of `conformesh field check`: what a sampled field (sampled_field.h) implies — topology,
// area, ∫K dA, the smallest det g — after the structural checks of sampled_field_checks.h and SampledMetric's
// per-sample checks have passed. Depends on sampled_metric.h and metric_quadrature.h.
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/sampled_field.h"
#include "conformesh/intrinsic/metric/sampled_field_checks.h"

namespace conformesh::intrinsic {

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
