// smooth_reference.h — a mesh of a smooth metric against the metric itself: total area and total curvature ∫K dA of
// the mesh (its lengths) beside the metric's, computed by adaptive quadrature over the chart (metric_quadrature.h
// metricArea, metricTotalCurvature). The first figures a relativist checks: the horizon area gives the irreducible
// mass √(A/16π), and ∫K dA = 2πχ (4π on a genus-0 horizon) checks the metric itself.
//
// Inputs: the output mesh of a remesh (Euclidean background, lengths in the original metric) and its metric.
// Outputs: SmoothReferenceComparison. A quadrature that stops above its tolerance (depth or evaluation budget: a
// metric that is only C¹) does not throw: its value comes with its error estimate (smooth*ErrorEstimate).
//
// What to expect: the mesh area is that of flat triangles with the edges' metric lengths, below the smooth area by
// O(ε²) (relative); the mesh's interior angle deficits are 2πχ − (boundary turning) exactly (discrete Gauss–Bonnet),
// so on a closed surface they equal ∫K dA = 2πχ to round-off and the difference checks the quadrature and the
// metric; with boundary, ∫K dA over the chart differs from the deficits by ∫k_g ds against the boundary polygon's
// turning, O(ε) (docs/theory.md §5).
#pragma once

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

struct SmoothReferenceComparison {
  double meshArea = 0;    // Σ triangle areas from the mesh's lengths
  double smoothArea = 0;  // ∫ √det g du dv over the chart (relative tolerance 1e-12)
  double areaRelativeDifference = 0;  // (meshArea − smoothArea) / smoothArea
  double smoothAreaErrorEstimate = 0;
  // Σ over interior vertices of 2π − Σθ (the discrete ∫K dA; boundary turning left out, as ∫k_g ds is on the smooth
  // side).
  double meshTotalCurvature = 0;
  double smoothTotalCurvature = 0;  // ∫ K √det g du dv over the chart (absolute tolerance 1e-10)
  double smoothTotalCurvatureErrorEstimate = 0;
  double totalCurvatureDifference = 0;  // meshTotalCurvature − smoothTotalCurvature (∫K dA is dimensionless)
  // totalCurvatureDifference / |smoothTotalCurvature|; NaN when |smoothTotalCurvature| < kZeroTotalCurvature (a torus
  // or a flat patch: only the absolute difference means something there).
  double totalCurvatureRelativeDifference = 0;
  int eulerCharacteristic = 0;
  int boundaryLoops = 0;
};

// ∫K dA is dimensionless; below this (four digits above the quadrature's 1e-10 tolerance) it counts as zero.
constexpr double kZeroTotalCurvature = 1e-6;

SmoothReferenceComparison compareWithSmoothMetric(const IntrinsicTriangulation& mesh, const SmoothMetric& metric);

}  // namespace conformesh::intrinsic
