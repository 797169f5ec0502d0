// smooth_reference.cpp — mesh area and ∫K dA against the metric's quadratures (see smooth_reference.h).
#include "conformesh/intrinsic/measure/smooth_reference.h"

#include <cmath>
#include <limits>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::intrinsic {

SmoothReferenceComparison compareWithSmoothMetric(const IntrinsicTriangulation& mesh, const SmoothMetric& metric) {
  SmoothReferenceComparison c;
  // A diagnostic beside a finished mesh, so a quadrature that stops above its tolerance (a metric that is only C¹,
  // e.g. γ interpolated from a grid, sampled_spatial_metric.h) reports its value with its error estimate instead of
  // throwing: the comparison states how far the reference can be trusted.
  QuadratureOptions areaRule, curvatureRule;  // curvature: the defaults, 1e-10 absolute and relative
  areaRule.absoluteTolerance = areaRule.relativeTolerance = 1e-12;
  areaRule.throwOnFailure = curvatureRule.throwOnFailure = false;
  // A budget of 2·10⁵ evaluations each. The analytic families converge with far fewer; a metric that is only C¹ (γ
  // interpolated from a grid: its K needs second derivatives, ~15–20 µs an evaluation) never reaches the tolerance
  // and spends the whole budget: measured on the 40³ Kerr–Schild grid of test_horizon_command, 10⁶ each took 29 s of a
  // 33 s remesh. At 2·10⁵ it takes about 6 s there; the area's estimate (3·10⁻⁷) still resolves the mesh's O(ε²)
  // difference (1.5·10⁻³), while a C¹ metric's ∫K dA is only known to its reported estimate (2πχ is exact anyway).
  areaRule.maxEvaluations = curvatureRule.maxEvaluations = 200'000;
  const QuadratureResult area = metricArea(metric, areaRule);
  const QuadratureResult curvature = metricTotalCurvature(metric, curvatureRule);
  const CurvatureTotals totals = curvatureTotals(mesh);
  c.meshArea = totalArea(mesh);
  c.smoothArea = area.value;
  c.smoothAreaErrorEstimate = area.errorEstimate;
  c.areaRelativeDifference = (c.meshArea - c.smoothArea) / c.smoothArea;
  c.meshTotalCurvature = totals.interiorDeficit + totals.backgroundTerm;
  c.smoothTotalCurvature = curvature.value;
  c.smoothTotalCurvatureErrorEstimate = curvature.errorEstimate;
  c.totalCurvatureDifference = c.meshTotalCurvature - c.smoothTotalCurvature;
  c.totalCurvatureRelativeDifference = std::abs(c.smoothTotalCurvature) < kZeroTotalCurvature
                                           ? std::numeric_limits<double>::quiet_NaN()
                                           : c.totalCurvatureDifference / std::abs(c.smoothTotalCurvature);
  c.eulerCharacteristic = totals.eulerCharacteristic;
  c.boundaryLoops = static_cast<int>(mesh.mesh.boundaryLoops().size());
  return c;
}

}  // namespace conformesh::intrinsic
