// gaussian_curvature_measure.h — the paper's convergence check, intrinsic (eqs. 1, 5 and Theorem 3.4): for each vertex v
// of an output mesh T, a region B_v (a union of triangles around v), the discrete measure φ_T(B_v) = Σ angle deficits of
// the vertices interior to B_v, against the smooth measure φ_M(η(B_v)) = ∫ K dA over the part of the smooth surface
// that B_v maps to, integrated with the metric's own K — independently of the mesh's angles.
//
// T's vertices sit on the smooth surface as points of the chart's pole-free reference surface (smooth_metric.h:
// referencePoint); each triangle of T maps to the reference triangle spanned by its three points (straight in the plane
// or on the torus/cylinder chart, gnomonic — a geodesic triangle — on the reference sphere), which is the natural
// projection η of the paper's §4.4 for the piecewise-linear parametrization it uses (§5.1.2).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/intrinsic_triangulation.h"
#include "conformesh/intrinsic/metric_quadrature.h"
#include "conformesh/intrinsic/smooth_metric.h"

namespace conformesh::intrinsic {

// Which region around each vertex v is compared.
enum class MeasureRegion {
  // B_v = {p : d(p, v) < r}, d the mesh's graph-geodesic distance from v (Dijkstra along edges), interpolated linearly
  // inside triangles. φ_T(B_v) = Σ deficits of the vertices in B_v; φ_M = ∫K dA over the image of the same region,
  // triangles cut by the level set d = r included in part. This is the paper's experiment (§6.2, balls B(q, r)) made
  // intrinsic: atoms near the ball's rim fall in or out with no systematic bias.
  GeodesicBall,
  // B_v = the union of triangles whose three vertices are within d < r, and φ_T its interior vertices' deficits: the
  // setting of Theorem 3.4 verbatim. The deficits of vertices on ∂B_v are left out, a one-sided O(ε·length(∂B)) term
  // the theorem's bound allows, so relative errors are biased by ≈ ε / r.
  TriangleUnion
};

struct CurvatureMeasureOptions {
  MeasureRegion region = MeasureRegion::GeodesicBall;
  // Ball radius r as a fraction of √(area of T): the paper uses 0.05 for the Gaussian measure (§6.2).
  double radiusFraction = 0.05;
  // The smooth side is integrated triangle by triangle with Radon's 7-point degree-5 rule on the pulled-back density
  // K √det g: for triangles of size h its error is O(h⁶) per unit area, ~10⁻¹⁰ relative at the coarsest meshes measured,
  // far below the O(ε) errors of the check (the tests compare Σ ∫K dA with 2πχ).
  // Histogram of relative errors over [−histogramRange, histogramRange] in `histogramBins` bins (paper Fig. 12:
  // ±0.1), and the band counted as "within" (paper: ±0.05).
  double histogramRange = 0.1;
  int histogramBins = 40;
  double withinBand = 0.05;
};

struct CurvatureMeasureResult {
  double radius = 0;                 // r used for the balls
  std::vector<double> discrete;      // φ_T(B_v) per vertex
  std::vector<double> smooth;        // φ_M(η(B_v)) per vertex
  std::vector<double> absoluteScale; // ∫ |K| dA over η(B_v): the normalization of relative errors (for a triangle cut
                                     // by the rim, its ∫|K| times the share of its barycentric area inside)
  std::vector<double> relativeError; // (φ_T − φ_M) / ∫|K| dA; 0 where the ball is flat (scale 0)
  double meanAbsoluteError = 0;      // the paper's e_G
  double maxAbsoluteError = 0;
  double fractionWithinBand = 0;     // of vertices with |relative error| < withinBand
  std::vector<int> histogram;        // counts per bin; out-of-range errors go to the end bins
  // Σ over all triangles of ∫K dA: the smooth total curvature over the region the mesh covers (2πχ for a closed
  // surface, by Gauss–Bonnet), a check that the triangles' images tile the surface.
  double smoothTotalCurvature = 0;
};

// `referencePoints` holds one point per vertex of `mesh`, on the reference surface of `metric`'s chart. The mesh must be
// Euclidean (output lengths measured in the original metric). The regions B_v are chosen by options.region.
CurvatureMeasureResult gaussianCurvatureMeasure(const IntrinsicTriangulation& mesh,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const SmoothMetric& metric,
                                                const CurvatureMeasureOptions& options = {});

// The chart images of one mesh triangle, for callers that integrate other densities over it: the integral of f(u, v)
// over the reference triangle (xa, xb, xc) pulled back to the chart, with periodic seams unwrapped.
QuadratureResult integrateOverReferenceTriangle(const SmoothMetric& metric, const ChartFunction& density,
                                                const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                                const Eigen::Vector3d& xc, const QuadratureOptions& options = {});

}  // namespace conformesh::intrinsic
