// isometric_embedding.h — vertex positions in R³ whose straight edges have the lengths of an intrinsic triangulation,
// fitted by Ceres (Levenberg–Marquardt, sparse normal Cholesky), with a verdict on whether the fit is isometric.
// Residuals r_e = (|x_i − x_j| − ℓ_e) / ℓ_e per edge. A metric with no isometric embedding (the Kerr horizon at
// a/M > √3/2) leaves a residual that no start removes, and the result says so. Why the system is (nearly) square,
// the landmark-MDS start, the regularizer and the tolerance: docs/embedding.md, "Isometric embedding by Ceres".
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
  // Verdict threshold on the largest relative edge residual: realizable lengths fit to ~1e-15…1e-12, lengths without a
  // realization leave ≳ 1e-5; docs/embedding.md ("Isometric embedding by Ceres") explains the choice.
  double tolerance = 1e-8;
  // Weight w of the dihedral-smoothness regularizer of the first solve: per interior edge the residual 2w·sin(β/2),
  // β the signed angle between its faces' unit normals. The first solve runs in three stages w, w/10, w/100 (inexact
  // CGNR steps), the second drops it (w = 0, exact SPARSE_NORMAL_CHOLESKY steps) so the positions answer to the lengths
  // alone; 0 skips the first solve. docs/embedding.md derives the stages and the default.
  double regularizerWeight = 1;
  int maxIterationsRegularized = 100;  // per stage of the first solve
  int maxIterations = 200;
  // Threads for Ceres (Jacobian evaluation); the machine is usually shared, hence 1.
  int threads = 1;
  // One line per LM iteration ("fit iteration 7: cost …, max step …") and per stage.
  std::function<void(const std::string&)> progress;

  // What is wrong with these options ("" when valid): tolerance finite and > 0, regularizerWeight finite and ≥ 0.
  // (initialPositions are checked against the mesh by fitIsometricEmbedding.)
  std::string validate() const;
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
