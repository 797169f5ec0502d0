// ricci_flow.h — the discrete Yamabe/Ricci flow by vertex scaling: Newton's method for the conformal factor u whose
// angle sums Θ are a prescribed Θ̂ (interior 2π − K̂, boundary π − k̂), the critical point of the convex energy of
// Springborn–Schröder–Pinkall 2008 / Bobenko–Pinkall–Springborn 2015, with Ptolemy flips keeping the triangulation
// Delaunay (Gu–Luo–Sun–Wu 2018) and an Armijo line search that accepts a decrease of ½|Θ̂ − Θ|² or, for Euclidean
// problems without circle loops, of that energy (conformal_energy.h; docs/ricci_flow.md §2 "The energy and the line
// search"). Hyperbolic problems and circle loops (whose targets follow the metric: no energy) use ½|Θ̂ − Θ|² alone.
//
// Touches only the DiscreteConformalMetric it is given (u and connectivity), the correspondence log and an optional
// shared solver cache. Derivations, the linear algebra and the stopping rule: docs/ricci_flow.md §2 (circle loops
// §3.3).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic {

// What the flow is asked to reach.
struct ConformalTarget {
  // Per vertex: the target sum of corner angles (over non-frozen faces). Ignored for fixed vertices.
  std::vector<double> angleSum;
  // Per vertex: 1 = u_i is held at its current value (Dirichlet). May be empty (no vertex fixed).
  std::vector<char> fixed;
  // Boundary loops that must become circles (Euclidean only). Their vertices' targets follow the metric,
  // Θ̂_v = π − σ (φ_prev + φ_next) from inscribedPolygon (docs/ricci_flow.md §3.3); their angleSum entries are ignored.
  struct CircleLoop {
    std::vector<int> edges;     // boundary edges in order along the loop
    std::vector<int> vertices;  // vertices[j] joins edges[j] and edges[j+1]
    double sign = 1;            // σ: +1 for the outer loop (counter-clockwise), −1 for holes
  };
  std::vector<CircleLoop> circleLoops;
};

// The convex polygon with side lengths `sides` inscribed in a circle: radius R, per side the half central angle φ_j
// (Σ φ_j = π; φ_p + φ_n is the turning angle between sides p and n) and the sign of dφ_j/d(ℓ_j/2R). Throws
// ConvergenceError naming `loop` when one side is at least the sum of the others (no such polygon).
struct InscribedPolygon {
  double radius = 0;
  std::vector<double> halfAngle;  // φ_j per side, radians
  std::vector<signed char> side;  // ±1 per side: −1 only for the longest side when the centre lies outside
};
InscribedPolygon inscribedPolygon(const std::vector<double>& sides, int loop);

struct NewtonStepInfo {
  int step = 0;
  double maxResidual = 0;  // max_i |Θ̂_i − Θ_i| before the step
  double stepLength = 0;   // the accepted t
  std::int64_t flips = 0;  // flips during this step's line search
};

// Linear-algebra state that consecutive solves on one metric may share (RicciFlowOptions::solverCache): the last
// Cholesky factor of the Hessian, which preconditions the next solve's conjugate gradients, and the solve's arrays.
// Private (src/flow/flow_solver_cache.h); the arguments are those of RicciFlowOptions.
class FlowSolverCache;
std::shared_ptr<FlowSolverCache> makeFlowSolverCache(int maxReuseIterations = 20, int nestedDissectionMin = 300000);

struct RicciFlowOptions {
  // Stop when max_i |Θ̂_i − Θ_i| ≤ max(tolerance, relativeFloor · sqrt(#vertices)) (radians). The floor grows with
  // the vertex count because the Hessian's condition does; 3e-13 leaves 1e-10 in force below ~10⁵ vertices.
  double tolerance = 1e-10;
  double relativeFloor = 3e-13;
  int maxNewtonSteps = 100;
  // Newton systems after the first are solved by conjugate gradients preconditioned with the last Cholesky factor;
  // when they do not converge in this many iterations the Hessian is factored anew (0: factor at every step).
  int maxReuseIterations = 20;
  // From this many unknowns on, the Cholesky factorization uses SCOTCH nested dissection (src/flow/linalg/
  // fill_reducing_order.h), below CHOLMOD's own order; the default is where ordering time starts to pay off. Changes
  // round-off only.
  int nestedDissectionMin = 300000;
  // Optional: share the factor with other solves (makeFlowSolverCache). Dirichlet vertices then stay unknowns with
  // identity rows, so that changes of the Dirichlet set keep the dimension. Ignored for circle loops.
  std::shared_ptr<FlowSolverCache> solverCache;
  // Armijo constant on the merit ½|r|² and on the energy (0 < armijo < 0.5) and the smallest step length before giving
  // up (0 < minStep ≤ 1).
  double armijo = 1e-4;
  double minStep = 1e-12;
  // The line search's first trial is the largest t = 2^-k with t · max|δ| ≤ maxTrialStep (> 0; radians of u): a trial
  // that moves some u by more than this rescales a length by up to e^16 and is rejected after Ptolemy flips that the
  // flip log keeps (lion.off: 5·10⁶ flips in one step's rejected trials; docs/ricci_flow.md §2).
  double maxTrialStep = 16;
  // Delaunay tolerance of the Penner flips (see pennerDelaunayMargin): 1e-12 leaves cocircular quads alone.
  double delaunayTolerance = 1e-12;
  // Return a solution that contains faces with extended angles (π, 0, 0) instead of throwing; the genus-0
  // construction repairs them by flipping edges of the puncture's star and solving again.
  bool allowDegenerateFaces = false;
  // With allowDegenerateFaces: return early (RicciFlowReport::stoppedAtDegenerate) as soon as the full Newton step is
  // rejected while some face has the extended angles (π, 0, 0), where Newton steps are poor (docs/ricci_flow.md §3.1).
  bool returnAtDegenerateStall = false;
  // Called after every Newton step (for progress lines); may be empty.
  std::function<void(const NewtonStepInfo&)> onStep;
  // Called after every accepted Newton step that has not yet reached the tolerance, with each vertex's angle sum Θ over
  // the non-frozen faces and max_i |Θ̂_i − Θ_i| at that point; returning true ends the flow there
  // (RicciFlowReport::stoppedByCaller, not converged). The genus-0 caller stops as soon as a link vertex of the
  // puncture is clearly reflex, instead of converging a problem whose star is about to change. May be empty.
  std::function<bool(const std::vector<double>& angleSums, double maxResidual)> stopAfterStep;

  // What is wrong with these options ("" when valid), as "RicciFlowOptions::<field>: expected …, found …".
  std::string validate() const;
};

struct RicciFlowReport {
  int newtonSteps = 0;
  std::int64_t flips = 0;
  double maxResidual = 0;  // at exit
  double effectiveTolerance = 0;
  double seconds = 0;
  std::vector<double> circleRadii;   // per circle loop, at exit
  bool gaugeFixed = false;           // a vertex was pinned (Euclidean problem without Dirichlet vertices)
  int factorizations = 0;            // sparse Cholesky factorizations (symmetric problems)
  int cgIterations = 0;              // preconditioned conjugate-gradient iterations that reused a factor
  bool stoppedAtDegenerate = false;  // returned early by returnAtDegenerateStall (not converged)
  bool stoppedByCaller = false;      // returned early because stopAfterStep said so (not converged)
  std::vector<double> angleSums;     // Θ per vertex over the non-frozen faces at exit (as flowAngleSums)
  bool nestedDissection = false;     // the last analysis used SCOTCH nested dissection (nestedDissectionMin)
  // Refinement steps of the precision fallback (0: not used): double stalled at round-off, the residual was evaluated
  // in long double and maxResidual/angleSums are those of the extended-precision u, which u rounds (ricci_flow.md §2).
  int extendedPolishSteps = 0;
};

// Solves for u from the current one: on return `metric` has the flow's u and Delaunay connectivity, `log` (may be null)
// the flips. Throws InputError for invalid options (RicciFlowOptions::validate) or an invalid target (sizes, Θ̂ not
// finite and positive at a free vertex, Gauss–Bonnet Σ K̂ = 2πχ for closed Euclidean problems without frozen faces,
// positive area for hyperbolic ones, spherical background), naming the vertex or the imbalance; ConvergenceError with
// the residual reached when the step cap is hit, the line search stalls, the Hessian is singular or the solution has
// a degenerate face. docs/ricci_flow.md §2.
RicciFlowReport solveConformalFlow(DiscreteConformalMetric& metric, const ConformalTarget& target,
                                   const RicciFlowOptions& options = {}, FlowCorrespondence* log = nullptr);

// Per vertex: Σ of corner angles over the non-frozen faces at the current u (valid Delaunay state assumed).
std::vector<double> flowAngleSums(const DiscreteConformalMetric& metric);

}  // namespace conformesh::intrinsic
