// mean_curvature_measure.h — the paper's extrinsic convergence check (eqs. 2 and 4–6, Theorem 3.4; §6.2): per vertex v
// of a mesh T in R³, the ball B = B(v, r), r = 0.08·√area, and
//   discrete  φ_T^H(B) = Σ_e |e ∩ B| β(e)       (eq. 2; β(e) the signed dihedral angle, positive on convex edges)
//   smooth    φ_M^H(B) = ∫_{B ∩ M} (κ₁ + κ₂) dA  (over the surface points inside the same ball)
// "H" is the SUM of the principal curvatures; boundary edges contribute nothing. The smooth side uses the metric's
// embedding (embedded_surface.h). Reads the mesh and the surface only. docs/embedding.md has the derivation.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/extrinsic/embedded_surface.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::embedding {

struct MeanCurvatureMeasureOptions {
  // Ball radius r as a fraction of √(area of T): 0.08 in the paper for the mean curvature measure (§6.2).
  double radiusFraction = 0.08;
  // Each triangle's image η(t) is split into 4^subdivision sub-triangles integrated by the degree-2 edge-midpoint rule
  // (error O(h⁴)); a sub-triangle cut by ∂B counts with its part inside the quadratic interpolant of |X − v| − r
  // (rim error O(h³)). 0..6.
  int subdivision = 1;
  // Histogram of relative errors over [−histogramRange, histogramRange] (the paper's Fig. 12 uses ±0.1) and the band
  // counted as "within" (paper: ±0.05).
  double histogramRange = 0.1;
  int histogramBins = 40;
  double withinBand = 0.05;

  // What is wrong with these options ("" when valid): subdivision in 0..6, positive radius fraction and histogram
  // range, at least one bin.
  std::string validate() const;
};

struct MeanCurvatureMeasureResult {
  double radius = 0;
  std::vector<double> discrete;       // φ_T^H(B_v) per vertex
  std::vector<double> smooth;         // φ_M^H(B_v) per vertex
  std::vector<double> absoluteScale;  // ∫_{B ∩ M} |κ₁ + κ₂| dA: the normalization of the relative errors
  std::vector<double> relativeError;  // (φ_T − φ_M)/scale; 0 where the scale is 0 (flat ball)
  double meanAbsoluteError = 0;       // the paper's e_H (§6.2): mean over vertices of |φ_T − φ_M| (as e_G in
                                      // gaussian_curvature_measure.h: absolute, not normalized)
  double maxAbsoluteError = 0;        // max |φ_T − φ_M|
  double meanRelativeError = 0;       // mean |relative error|
  double fractionWithinBand = 0;
  std::vector<int> histogram;
  // Whole-surface totals: Σ_e |e| β(e) and ∫_M (κ₁ + κ₂) dA over the mesh's image (4π·(mean width)… — for a closed
  // convex surface the total mean curvature; for a sphere of radius R, 8πR).
  double discreteTotal = 0, smoothTotal = 0;
};

// `positions` are the vertices in R³, `referencePoints` their points on the chart's reference surface (η of the
// vertices; remesh's `reference`). The mesh must be Euclidean. Throws InputError for arrays of the wrong size or
// non-finite entries, and when the metric has no embedding.
MeanCurvatureMeasureResult meanCurvatureMeasure(const intrinsic::IntrinsicTriangulation& mesh,
                                                const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const EmbeddedSurface& surface,
                                                const MeanCurvatureMeasureOptions& options = {});

// β(e): the signed angle between the unit normals of the two faces at interior edge e (positive where the mesh is
// convex with respect to its orientation), atan2((n₁ × n₂)·ê, n₁·n₂); 0 on boundary edges.
double signedDihedralAngle(const intrinsic::HalfedgeMesh& mesh, const std::vector<Eigen::Vector3d>& positions, int e);

// The length of segment [a, b] inside the closed ball of centre c and radius r.
double segmentLengthInBall(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double r);

}  // namespace conformesh::embedding
