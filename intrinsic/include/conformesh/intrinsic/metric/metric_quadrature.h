// metric_quadrature.h — adaptive quadrature over regions of a chart: rectangles, chart triangles (and unions of them),
// polygons, and regions given by a membership predicate; with the area density √det g and the curvature density
// K √det g of a SmoothMetric this gives areas and ∫K dA (the smooth side of paper eq. 5's curvature measure).
//
// Rule: tensor Gauss–Legendre with n×n nodes on a cell (rectangle, or a triangle through the collapsed/Duffy map), the
// cell's error estimated as |Q(cell) − Σ Q(children)| (rectangles halved along the direction that changes the value
// more, triangles split in four); globally adaptive like QUADPACK's qag: the cell with the largest estimate is split
// until the summed estimate meets the tolerance. For smooth integrands the returned (children) sums are far more
// accurate than the estimate says.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

using ChartFunction = std::function<double(double u, double v)>;

struct QuadratureOptions {
  // Stop when the estimated error is below max(absoluteTolerance, relativeTolerance·|value|). The defaults (1e-10)
  // sit four digits above round-off of sums of ~1e4 cell values, so they are reachable for smooth integrands.
  double absoluteTolerance = 1e-10;
  double relativeTolerance = 1e-10;
  int gaussPoints = 8;  // n: nodes per direction on a cell (exact for bi-degree 2n − 1 on rectangles)
  int maxDepth = 40;    // subdivision levels below the initial cells (rectangles halve along one side per level)
  // Budget of integrand evaluations (≈ 1 s for a cheap integrand); refinement stops when it is spent.
  long maxEvaluations = 10'000'000;
  // When the depth limit or the budget stops refinement above tolerance: throw ConvergenceError (default), or return
  // the value with its (large) error estimate — what predicate regions, whose boundaries converge only at first order,
  // usually want.
  bool throwOnFailure = true;
};

struct QuadratureResult {
  double value = 0;
  double errorEstimate = 0;
  long evaluations = 0;
};

// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n from Chebyshev guesses, to full double accuracy).
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

// The same rule, computed once per n on first use (thread-safe) and kept for the process: what per-call users (every
// output edge's length, every cell of integrateOverRectangle/Triangle) read instead of recomputing the nodes; also
// mapped to [0, 1] (x ↦ (x + 1)/2, w ↦ w/2) for the cell rules. Throws InputError outside 1..64.
struct GaussLegendreRule {
  std::vector<double> nodes, weights;          // on [−1, 1]
  std::vector<double> unitNodes, unitWeights;  // on [0, 1]
};
const GaussLegendreRule& gaussLegendreRule(int n);

// The Gauss–Kronrod pair G7–K15 on [−1, 1] (Kronrod 1965; the tables of QUADPACK's dqk15, Piessens et al. 1983):
// the 15 Kronrod nodes ±x_k in decreasing order with x_7 = 0, their weights, and the weights of the 7-point
// Gauss–Legendre rule on the odd-indexed nodes x_1, x_3, x_5, x_7. K15 integrates polynomials of degree ≤ 22 exactly,
// G7 those of degree ≤ 13; |K15 − G7| estimates G7's error, far above K15's own for a smooth integrand.
struct GaussKronrod15 {
  static constexpr int kNodes = 8;             // x_0..x_7 ≥ 0; the rule uses ±x_k
  static const double nodes[kNodes];           // x_0 = 0.9914… down to x_7 = 0
  static const double kronrodWeights[kNodes];  // K15 weight of ±x_k
  static const double gaussWeights[4];         // G7 weight of ±x_{2j+1}, j = 0..3
};

QuadratureResult integrateOverRectangle(const ChartFunction& f, double u0, double u1, double v0, double v1,
                                        const QuadratureOptions& options = {});
// Either orientation; the result is ∫ f over the triangle (non-negative measure).
QuadratureResult integrateOverTriangle(const ChartFunction& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       const Eigen::Vector2d& c, const QuadratureOptions& options = {});
// Union of chart triangles with disjoint interiors (e.g. the chart images of a T1 vertex's star): one global
// refinement over all of them, so the tolerance applies to the sum.
QuadratureResult integrateOverTriangles(const ChartFunction& f, const std::vector<std::array<Eigen::Vector2d, 3>>& tris,
                                        const QuadratureOptions& options = {});
// Simple polygon (either orientation), as a signed fan of triangles from its first vertex: f must be defined on the
// polygon's convex hull.
QuadratureResult integrateOverPolygon(const ChartFunction& f, const std::vector<Eigen::Vector2d>& polygon,
                                      const QuadratureOptions& options = {});
// Region {inside(u,v)} within the rectangle [u0,u1]×[v0,v1] (e.g. a geodesic ball): the integrand f·1_inside.
QuadratureResult integrateOverRegion(const ChartFunction& f, double u0, double u1, double v0, double v1,
                                     const std::function<bool(double, double)>& inside,
                                     const QuadratureOptions& options = {});

// === metric densities
ChartFunction areaDensity(const SmoothMetric& m);       // √det g
ChartFunction curvatureDensity(const SmoothMetric& m);  // K √det g
// Over the whole chart (polar charts included: the densities vanish like sin v at poles and are smooth there).
QuadratureResult metricArea(const SmoothMetric& m, const QuadratureOptions& options = {});
QuadratureResult metricTotalCurvature(const SmoothMetric& m, const QuadratureOptions& options = {});

}  // namespace conformesh::intrinsic
