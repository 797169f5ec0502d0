// mean_curvature_measure.h — the paper's extrinsic convergence check (eqs. 2 and 4–6, Theorem 3.4; §6.2): for each
// vertex v of a mesh T in R³, the ball B = B(v, r) and
//   discrete  φ_T^H(B) = Σ_e |e ∩ B| β(e)                       (eq. 2, the normal-cycle form of Cohen-Steiner–Morvan:
//                                                                 |e ∩ B| the length of the edge inside the ball,
//                                                                 β(e) the signed angle between its faces' normals,
//                                                                 positive on convex edges)
//   smooth    φ_M^H(B) = ∫_{B ∩ M} (κ₁ + κ₂) dA                  (over the surface points inside the same ball)
// with r = 0.08·√area as in the paper's §6.2. The smooth side uses the metric's embedding (embedded_surface.h).
//
// Convention: Σ |e| β(e) over a fine mesh tends to ∫ (κ₁ + κ₂) dA (a prism around a cylinder of radius R, length ℓ:
// Σ |e| β = 2πℓ = ∫ 1/R dA), so "H" in eq. 2 is the SUM of the principal curvatures — twice the average mean
// curvature. Boundary edges have no β and contribute nothing (the boundary terms of the normal cycle are left out).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/extrinsic/embedded_surface.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::embedding {

struct MeanCurvatureMeasureOptions {
  // Ball radius r as a fraction of √(area of T): 0.08 in the paper for the mean curvature measure (§6.2).
  double radiusFraction = 0.08;
  // The smooth integral is assembled from the mesh's triangles: each triangle's image (η: the reference triangle
  // mapped to the surface) is split into 4^subdivision sub-triangles, each integrated with the degree-2 edge-midpoint
  // rule (error O(h⁴) per unit area for sub-triangles of size h: 2e-6 relative on the whole ellipsoid at h ≈ 0.07). A
  // sub-triangle cut by the sphere ∂B counts with its part where the quadratic interpolant of |X − v| − r through its
  // corners and edge midpoints is negative (rim error O(h³); 1e-4 relative on the sphere's balls at h/r ≈ 0.25),
  // far below the e_H ~ ε measured.
  int subdivision = 1;
  // Histogram of relative errors over [−histogramRange, histogramRange] (the paper's Fig. 12 uses ±0.1) and the band
  // counted as "within" (paper: ±0.05).
  double histogramRange = 0.1;
  int histogramBins = 40;
  double withinBand = 0.05;
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
