// isometric_embedding.h — vertex positions in R³ whose straight edges have the lengths of an intrinsic triangulation,
// fitted by Ceres (Levenberg–Marquardt, sparse normal Cholesky), with a verdict on whether the fit is isometric.
//
// Unknowns: x_i ∈ R³ per vertex. Residuals: r_e = (|x_i − x_j| − ℓ_e) / ℓ_e per edge (relative, so every edge counts
// alike whatever its size). A closed genus-0 mesh has E = 3V − 6 edges: the system is square up to the six rigid
// motions, and the lengths of a fine mesh of a convex surface determine the polyhedron (Cauchy–Dehn–Alexandrov
// rigidity), so a mesh that comes from a surface in R³ is fitted to round-off. A metric with no isometric embedding
// (the Kerr horizon at a/M > √3/2, Smarr 1973) leaves a residual no start removes, and the result says so.
// Genus g ≥ 1 adds 6g equations: curve lengths then leave an O(ε²) residual even for an embedded torus (see
// docs/embedding.md), so the verdict is about the length set, not the smooth surface.
// docs/embedding.md explains the start (landmark MDS), the regularizer and the tolerance.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::embedding {

struct EmbeddingOptions {
  // Start positions, one per vertex (e.g. a known embedding, or the previous fit of a coarser mesh carried over).
  // Empty: a landmark classical-MDS start (de Silva–Tenenbaum 2004) from graph-geodesic (Dijkstra) distances.
  std::vector<Eigen::Vector3d> initialPositions;
  // Landmarks for the MDS start: farthest-point samples; k·V log V Dijkstra work and a k×k eigenproblem.
  int landmarks = 48;
  // Verdict threshold on the largest relative edge residual. A length set that some polyhedron realizes is fitted to
  // round-off — relative residuals ~1e-15…1e-12: the Jacobian's conditioning (~ number of vertices) times double
  // precision — while a metric without a realization leaves residuals of the size of the defect it cannot absorb,
  // ≳ 1e-5 for meshes coarse enough to fit at all. 1e-8 sits far from both.
  double tolerance = 1e-8;
  // Weight w of the dihedral-smoothness regularizer of the first solve: per interior edge the residual 2w·sin(β/2), β
  // the signed angle between the unit normals n₁, n₂ of its two faces, whose square is w²|n₁ − n₂|². From a rough start
  // it steers LM away from folded configurations: a vertex popped inward (the same edge lengths, a different
  // polyhedron) has |n₁ − n₂| = O(1) on its star, a smooth surface O(ε·κ). The first solve runs in three stages, w,
  // w/10 and w/100, each from the previous optimum, so that the regularizer's bias shrinks before the second solve
  // drops it (w = 0) and the final positions answer to the lengths alone: started from the w optimum directly, the
  // second solve popped vertices at 50 412 vertices (docs/embedding.md). On ellipsoid meshes of 640–5700 vertices 0.01
  // let popped vertices through, 0.1 and 1 did not. The default is 1 because the regularizer must also stiffen the
  // smooth bending modes, which the edge lengths of a fine mesh barely constrain: for a bending mode of fixed
  // wavelength its energy does not depend on h while the edge terms' grows like 1/h² (their number), so its relative
  // stiffness falls like h² (w ∝ 1/h keeps it), and at 198 812 vertices w = 0.1 let the first LM steps run off along
  // them (rejected, trust region collapsed, ≈ 0.3 % cost decrease per step thereafter), while w = 1 (and 0.32) took
  // accepted steps from the first; at 20 252 vertices w = 1 needs 7 regularized steps instead of 44 and reaches the
  // same convex realization. 0 skips the first solve. The first solve takes inexact LM steps (CGNR,
  // Jacobi-preconditioned conjugate gradients: it only has to reach the right basin, and its normal equations couple
  // 2-rings: an exact step cost ≈ 15× a second-solve step at 20k); the second takes exact ones (SPARSE_NORMAL_CHOLESKY,
  // nested-dissection order) to converge to round-off.
  double regularizerWeight = 1;
  int maxIterationsRegularized = 100;  // per stage of the first solve
  int maxIterations = 200;
  // Threads for Ceres (Jacobian evaluation); the machine is usually shared, hence 1.
  int threads = 1;
  // One line per LM iteration ("fit iteration 7: cost …, max step …") and per stage.
  std::function<void(const std::string&)> progress;
};

struct EmbeddingResult {
  std::vector<Eigen::Vector3d> positions;  // the best fit (also when it is not isometric)
  double maxRelativeResidual = 0;          // max_e |(|x_i − x_j| − ℓ_e)/ℓ_e|
  double rmsRelativeResidual = 0;          // √(mean of the squares)
  int worstEdge = -1;                      // where the max is attained
  bool isometric = false;                  // maxRelativeResidual ≤ tolerance
  double tolerance = 0;
  std::string verdict;  // "isometric to tolerance T (…)" or "not isometric: residual R cannot be removed (…)"
  std::string start;    // "initial positions" or "landmark MDS (k landmarks)"
  int regularizedIterations = 0, iterations = 0;    // LM iterations of the two solves
  double startSeconds = 0, fitSeconds = 0;          // wall time of the start and of both solves
  double regularizedSeconds = 0, finalSeconds = 0;  // fitSeconds split by solve
};

// Fits positions to `mesh`'s edge lengths. Throws InputError (naming the element) for: a non-Euclidean background, a
// mesh without faces, more than one connected component (the lengths do not fix the components' relative placement:
// split the mesh first), a self-loop edge (no straight segment joins a point to itself with positive length), invalid
// lengths, or initial positions of the wrong count or not finite. A fit that is not isometric is NOT an exception:
// the result carries the verdict and the best positions; callers that require isometry check `isometric`.
EmbeddingResult fitIsometricEmbedding(const intrinsic::IntrinsicTriangulation& mesh,
                                      const EmbeddingOptions& options = {});

// Relative residuals (|x_i − x_j| − ℓ_e)/ℓ_e of any positions, per edge.
std::vector<double> relativeEdgeResiduals(const intrinsic::IntrinsicTriangulation& mesh,
                                          const std::vector<Eigen::Vector3d>& positions);

// The MDS start alone (for tests and for callers that want to inspect it): positions whose pairwise distances
// approximate the graph-geodesic distances, scaled so that the RMS relative edge residual is smallest.
std::vector<Eigen::Vector3d> landmarkMdsStart(const intrinsic::IntrinsicTriangulation& mesh, int landmarks);

}  // namespace conformesh::embedding
