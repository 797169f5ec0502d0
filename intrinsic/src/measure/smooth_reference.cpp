// smooth_reference.cpp — mesh area and ∫K dA against the metric's quadratures (see smooth_reference.h).
#include "conformesh/intrinsic/measure/smooth_reference.h"

#include <cmath>
#include <limits>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::intrinsic {

SmoothReferenceComparison compareWithSmoothMetric(const IntrinsicTriangulation& mesh, const SmoothMetric& metric) {
  SmoothReferenceComparison c;
  QuadratureOptions areaRule;
  areaRule.absoluteTolerance = areaRule.relativeTolerance = 1e-12;
  const QuadratureResult area = metricArea(metric, areaRule);
  const QuadratureResult curvature = metricTotalCurvature(metric);  // defaults: 1e-10 absolute and relative
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
