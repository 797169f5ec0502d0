// gaussian_curvature_measure.h — the paper's convergence check, intrinsic (eqs. 1, 3, 5 and Theorem 3.4): for each
// vertex v of an output mesh T, the discrete measure φ_T(B_v) (angle deficits, and boundary turnings on a surface with
// boundary, of the vertices in a region B_v) against the smooth measure φ_M(η(B_v)) = ∫K dA (+ ∫k_g ds + corner
// turnings) over the part of the surface B_v maps to, integrated with the metric's own K — independently of the
// mesh's angles. The projection η and the regions: docs/theory.md §5.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

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

// On a surface with boundary the Gaussian curvature measure — the normal cycle's (paper §4.3), equivalently the one
// that makes Gauss–Bonnet local — has boundary atoms (docs/theory.md §5):
//   φ_M(B) = ∫_{B∩M} K dA + ∫_{B∩∂M} k_g ds + Σ_{corners c ∈ B} (π − α_c),
//   φ_T(B) = Σ_{interior v ∈ B} (2π − Σθ_v) + Σ_{boundary v ∈ B} (π − Σθ_v),
// both totalling 2πχ. The smooth surface compared is η(T), the image of the mesh: its boundary is the image of T's
// boundary edges (each the curve of a straight reference segment), with k_g from the metric's Christoffel symbols and
// a corner at every boundary vertex where two such curves meet at a metric angle α ≠ π. On a rectangle chart whose
// boundary vertices lie on the sides this is the chart's sides (k_g of the coordinate curves) and its four corners;
// on a disk chart (spherical cap, hyperbolic disk) it is the inscribed polygon's chords, whose k_g and small turnings
// add up to the circle's ∫k_g ds to O(h²) (the triangles tile that polygon, not the disk).

// How the all-vertex check sweeps its balls (GeodesicBall regions; TriangleUnion regions are always measured ball by
// ball). Both give the same numbers to round-off — the same distances bit for bit and the same terms, added in another
// order (docs/theory.md §5, "Cost"): per ball |Δφ_T| ≤ 2(k−1)u Σ|atoms|, |Δφ_M| ≤ 2(k−1)u |φ_M|(B) with k the
// ball's number of terms and u = 2⁻⁵³.
enum class BallSweepAlgorithm {
  // Patches of 16 neighbouring centres share one label-correcting Dijkstra whose 16 distance fields are carried side
  // by side, and the terms inside every ball of a patch are added once (the default; several times less CPU than
  // BallByBall from 10⁵ vertices on: docs/benchmarks.md). Still O(V²).
  Patches,
  // One Dijkstra per centre, the earlier algorithm, kept as the reference the tests compare with.
  BallByBall
};

struct CurvatureMeasureOptions {
  MeasureRegion region = MeasureRegion::GeodesicBall;
  // true (default): the boundary atoms above on both sides. false: interior vertices' deficits against ∫K dA only.
  // No effect on closed surfaces.
  bool boundaryTerms = true;
  // Ball radius r as a fraction of √(area of T): the paper uses 0.05 for the Gaussian measure (§6.2).
  double radiusFraction = 0.05;
  // Histogram of relative errors over [−histogramRange, histogramRange] in `histogramBins` bins (paper Fig. 12: ±0.1),
  // and the band counted as "within" (paper: ±0.05). The quadrature rules (Radon 7-point on ∫K dA, 4-point
  // Gauss–Legendre on ∫k_g ds) are fixed; docs/theory.md §5 gives their error orders.
  double histogramRange = 0.1;
  int histogramBins = 40;
  double withinBand = 0.05;
  // Called with (balls done, balls in all) after every hundredth of the balls and after the last; may be empty. The
  // check costs O(V²): each ball holds a fixed fraction of the vertices.
  std::function<void(int, int)> progress;
  BallSweepAlgorithm algorithm = BallSweepAlgorithm::Patches;
  // 0 (default): every vertex is a centre — the exact check. N > 0: a quick look at N distinct centres drawn uniformly
  // without replacement (SplitMix64 from `sampleSeed`, so a seed gives the same centres on every platform); e_G is
  // then the sample mean of |φ_T − φ_M| with a 95 % confidence interval (result.meanAbsoluteErrorHalfWidth). N ≥ the
  // vertex count measures every vertex.
  int sampleCentres = 0;
  unsigned long long sampleSeed = 1;

  // What is wrong with these options ("" when valid): radiusFraction > 0, sampleCentres ≥ 0, histogramBins ≥ 1,
  // histogramRange > 0.
  std::string validate() const;
};

struct CurvatureMeasureResult {
  double radius = 0;                  // r used for the balls
  std::vector<double> discrete;       // φ_T(B_v) per vertex
  std::vector<double> smooth;         // φ_M(η(B_v)) per vertex
  std::vector<double> absoluteScale;  // |φ_M|(η(B_v)), the total variation of the smooth measure on the ball: ∫|K| dA
                                      // (for a triangle cut by the rim, its ∫|K| times the share of its barycentric
                                      // area inside), plus ∫|k_g| ds and Σ |π − α| with boundary terms. The
                                      // normalization of relative errors.
  std::vector<double> relativeError;  // (φ_T − φ_M) / absoluteScale; 0 where the measure vanishes on the ball
  double meanAbsoluteError = 0;       // the paper's e_G (sampled mode: the sample mean)
  // Sampled mode (options.sampleCentres > 0): the centres measured, ascending — the per-vertex arrays above are NaN at
  // every other vertex and the statistics below are the sample's — and the half-width of the 95 % confidence interval
  // of e_G, 1.96·s/√N·√((V − N)/(V − 1)) (s the sample's standard deviation of |φ_T − φ_M|, the finite-population
  // correction for drawing without replacement; a normal approximation, fair for N ≳ 30). Exact mode: centres is empty
  // and the half-width 0.
  std::vector<int> centres;
  double meanAbsoluteErrorHalfWidth = 0;
  double maxAbsoluteError = 0;
  double fractionWithinBand = 0;  // of vertices with |relative error| < withinBand
  std::vector<int> histogram;     // counts per bin; out-of-range errors go to the end bins
  // Σ over all triangles of ∫K dA: the smooth total curvature over the region the mesh covers (2πχ for a closed
  // surface, by Gauss–Bonnet), a check that the triangles' images tile the surface.
  double smoothTotalCurvature = 0;
  // With boundary terms: Σ over T's boundary edges of ∫k_g ds plus Σ over its boundary vertices of π − α, so that
  // smoothTotalCurvature + smoothBoundaryCurvature = 2πχ (Gauss–Bonnet for η(T)); 0 otherwise.
  double smoothBoundaryCurvature = 0;
};

// `referencePoints` holds one point per vertex of `mesh`, on the reference surface of `metric`'s chart. The mesh must
// be Euclidean (output lengths measured in the original metric). The regions B_v are chosen by options.region. With
// boundary terms, a mesh with boundary on a sphere chart is rejected (InputError naming the boundary edge); on the
// other charts (planar or polar-disk reference) a mesh covering part of the surface is measured with η(T)'s boundary.
CurvatureMeasureResult gaussianCurvatureMeasure(const IntrinsicTriangulation& mesh,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const SmoothMetric& metric,
                                                const CurvatureMeasureOptions& options = {});

// The two measures of one region B = {p : d(p) < r}, d given at every vertex (`level`) and interpolated linearly inside
// triangles and along boundary edges, measured exactly as a GeodesicBall region (options.boundaryTerms applies;
// region, radiusFraction and the histogram fields are not used). For closed-form checks with exact distances.
struct RegionCurvatureMeasure {
  double discrete = 0, smooth = 0, absoluteScale = 0;
};
RegionCurvatureMeasure curvatureMeasureOfSublevelSet(const IntrinsicTriangulation& mesh,
                                                     const std::vector<Eigen::Vector3d>& referencePoints,
                                                     const SmoothMetric& metric, const std::vector<double>& level,
                                                     double r, const CurvatureMeasureOptions& options = {});

// The geodesic curvature at chart point `uv` of a chart curve with velocity `velocity` and acceleration `acceleration`
// (chart coordinates), signed against the chart's orientation: positive when the curve turns toward its left normal
// (c' rotated by +90° in the (u, v) orientation). k_g = √det g · det[c', ∇_{c'}c'] / |c'|³_g with
// ∇_{c'}c' = c'' + Γ(c', c') (do Carmo §4-4); for v = const, u increasing, it is √(EG − F²) Γ²₁₁ / E^{3/2}.
double geodesicCurvature(const SmoothMetric& metric, const Eigen::Vector2d& uv, const Eigen::Vector2d& velocity,
                         const Eigen::Vector2d& acceleration);

// The chart images of one mesh triangle, for callers that integrate other densities over it: the integral of f(u, v)
// over the reference triangle (xa, xb, xc) pulled back to the chart, with periodic seams unwrapped.
QuadratureResult integrateOverReferenceTriangle(const SmoothMetric& metric, const ChartFunction& density,
                                                const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                                const Eigen::Vector3d& xc, const QuadratureOptions& options = {});

}  // namespace conformesh::intrinsic
