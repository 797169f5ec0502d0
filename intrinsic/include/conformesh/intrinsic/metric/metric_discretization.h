// metric_discretization.h — T0: a well-shaped triangulation of a SmoothMetric's chart whose edge lengths are metric
// lengths (exact geodesic distances where the family knows them), as MeshData ready for toTriangulation().
//
// Closed surfaces come out closed and of the right topology without degenerate pole fans: sphere charts triangulate
// the unit sphere (a subdivided icosahedron, frequency N) and carry it through the chart; disk charts triangulate the
// plane disk by concentric hexagonal rings; tori and cylinders are periodic grids glued across the seams; rectangles
// are plain grids. Every T0 vertex keeps its chart coordinates as vertex properties "u" and "v"; the comments name the
// family, its parameters and how lengths were obtained. docs/metrics.md explains the construction and its accuracy.
#pragma once

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

struct DiscretizationOptions {
  // Sphere: icosahedral frequency N (10N² + 2 vertices). Disk: N rings (3N(N+1) + 1 vertices). Grids: N cells across
  // v, and in u as many as keep the cells near square in the metric (at least 3 when u is periodic).
  int resolution = 8;
  // Use the family's exact geodesic distance for an edge when it has one; otherwise (or when false) the metric length
  // of the edge's chart curve.
  bool exactGeodesics = true;
  // Gauss–Legendre nodes per piece of an edge's chart curve; pieces are halved until two successive composite sums
  // agree to lengthTolerance (relative). 1e-13 is ~500 ε, above the round-off of a sum of ~100 speeds.
  int gaussPoints = 10;
  double lengthTolerance = 1e-13;
  // The rule chartCurveLength applies. GaussLegendreHalving: the gaussPoints-node rule above, halving until two
  // successive composite sums agree (at least 3·gaussPoints speeds per curve). GaussKronrod15: the G7–K15 pair
  // (metric_quadrature.h) on the whole curve, K15 accepted when |K15 − G7| ≤ lengthTolerance·K15, else both halves
  // measured the same way (15 speeds per curve that is resolved at once; gaussPoints unused). |K15 − G7| estimates the
  // error of G7 (degree 13), so the accepted K15 (degree 22) is more accurate than the estimate states, as the
  // halving rule's finer sum is more accurate than the coarse one the test measures.
  enum class CurveRule { GaussLegendreHalving, GaussKronrod15 };
  CurveRule curveRule = CurveRule::GaussLegendreHalving;
};

struct DiscretizationReport {
  ChartShape shape = ChartShape::Rectangle;
  int vertices = 0, edges = 0, faces = 0;
  int exactLengths = 0;               // edges whose length is the family's exact geodesic distance
  double minAngle = 0, maxAngle = 0;  // radians, over all corners (from the edge lengths, Euclidean)
  double totalArea = 0;               // Σ Euclidean triangle areas of T0
};

MeshData discretizeMetric(const SmoothMetric& metric, const DiscretizationOptions& options = {},
                          DiscretizationReport* report = nullptr);

// The metric length of the curve that the reference-space segment from xa to xb traces in the chart (referencePoint /
// chartPoint of smooth_metric.h: a great arc on the unit sphere for sphere charts, a chord of the plane disk for disk
// charts, a straight chart segment (u, v, 0) otherwise, with u, v unwrapped across periodic seams).
double chartCurveLength(const SmoothMetric& metric, const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                        const DiscretizationOptions& options = {});

}  // namespace conformesh::intrinsic
