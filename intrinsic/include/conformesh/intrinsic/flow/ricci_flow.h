// ricci_flow.h — Newton's method for the discrete Yamabe/Ricci flow by vertex scaling: find u with prescribed angle
// sums Θ̂ (interior: 2π − K̂, boundary: π − k̂), the critical point of the convex Springborn–Schröder–Pinkall energy
// (Euclidean; hyperbolic form in Bobenko–Pinkall–Springborn 2015), with Ptolemy flips keeping the triangulation
// Delaunay so that every u is admissible (Gu–Luo–Sun–Wu 2018).
//
// The energy's gradient is Θ̂ − Θ(u) and its Hessian −∂Θ/∂u: the cotangent Laplacian in the Euclidean case, in general
// assembled per face from ∂θ_i/∂ℓ (dθ_i = ∂θ_i/∂ℓ_i (dℓ_i − cos θ_k dℓ_j − cos θ_j dℓ_k)) and ∂ℓ/∂u
// (discrete_conformal.h). It is solved by sparse Cholesky (CHOLMOD, supernodal), whose factor then preconditions
// conjugate gradients in the following steps until they stop converging quickly (inexact Newton). The step length
// satisfies Armijo's condition on the merit ½|Θ̂ − Θ|², for which the Newton direction is a descent direction with
// slope −|Θ̂ − Θ|²; because the Hessian is positive definite on the free variables, the merit's only stationary points
// are solutions, so this is a globally convergent alternative to Armijo on the energy that needs no Lobachevsky
// function (docs/ricci_flow.md).
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
  // Boundary loops that must become circles (Euclidean only). The targets of their vertices follow the metric: the
  // turning angles of the polygon with the loop's current side lengths inscribed in a circle (inscribedPolygon),
  // Θ̂_v = π − σ (φ_prev + φ_next), σ = +1 for the outer loop
  // (counter-clockwise) and −1 for holes. Newton then solves the coupled system with its exact, non-symmetric Jacobian
  // (sparse LU plus one rank-one term per loop for R, by Sherman–Morrison–Woodbury). The angleSum entries of these
  // vertices are ignored.
  struct CircleLoop {
    std::vector<int> edges;     // boundary edges in order along the loop
    std::vector<int> vertices;  // vertices[j] joins edges[j] and edges[j+1]
    double sign = 1;
  };
  std::vector<CircleLoop> circleLoops;
};

// The circle through the convex cyclic polygon with these sides: its radius R and per side the half central angle
// φ_j = asin(ℓ_j/2R), except that when the centre lies outside the polygon the longest side m has φ_m = π −
// asin(ℓ_m/2R); Σ φ_j = π. side[j] = ±1 is the sign of dφ_j/d(ℓ_j/2R). The turning angle at the vertex between sides
// p and n is φ_p + φ_n (inscribed angle theorem). Throws ConvergenceError naming `loop` when one side is at least the
// sum of the others (no such polygon).
struct InscribedPolygon {
  double radius = 0;
  std::vector<double> halfAngle;
  std::vector<signed char> side;
};
InscribedPolygon inscribedPolygon(const std::vector<double>& sides, int loop);

struct NewtonStepInfo {
  int step = 0;
  double maxResidual = 0;  // max_i |Θ̂_i − Θ_i| before the step
  double stepLength = 0;   // the accepted t
  std::int64_t flips = 0;  // flips during this step's line search
};

// Linear-algebra state that consecutive solves on one metric may share: the last Cholesky factor of the Hessian, which
// preconditions the next solve's conjugate gradients (the genus-0 construction solves, repairs the puncture's star
// and solves again; without sharing, each solve analyses and factors anew). Defined in ricci_flow.cpp.
class FlowSolverCache;
std::shared_ptr<FlowSolverCache> makeFlowSolverCache(int maxReuseIterations = 20, int nestedDissectionMin = 300000);

struct RicciFlowOptions {
  // Stop when max_i |Θ̂_i − Θ_i| ≤ tolerance (radians). 1e-10 is reachable in double precision up to ~10⁵ vertices;
  // for larger meshes the effective tolerance is max(tolerance, relativeFloor · sqrt(#vertices)), see below.
  double tolerance = 1e-10;
  // The round-off of an angle sum is a few ulps of 2π, but the Newton update comes from a Laplacian whose condition
  // number grows like #vertices, and on 10⁶-vertex inputs the residual floor approaches 1e-10 (the figure).
  // A bound growing like sqrt(#vertices) is a stated, not measured, choice: 3e-13 gives 3e-10 at 10⁶ vertices and
  // leaves 1e-10 in force below ~10⁵ (measured: a 10⁶-vertex torus stops at 2.5e-10 after one Newton step).
  double relativeFloor = 3e-13;
  int maxNewtonSteps = 100;
  // Newton systems after the first are solved by conjugate gradients preconditioned with the last Cholesky factor;
  // when they do not converge in this many iterations the Hessian is factored anew (0: factor at every step).
  int maxReuseIterations = 20;
  // From this many unknowns on, the Newton systems are ordered for the Cholesky factorization by SCOTCH's nested
  // dissection (speed strategy, src/fill_reducing_order.h); below, by CHOLMOD's default choice (AMD, plus METIS with
  // ten passes when AMD's fill is large). Measured on the genus-0 box (docs/benchmarks.md): at 10⁵ unknowns CHOLMOD
  // keeps AMD, and METIS would cost 0.5 s to save ≈ 0.1 s of factorization (the threshold was set with METIS); at 10⁶
  // CHOLMOD's analysis takes ≈ 9 s, METIS alone 5.4–7.8 s, SCOTCH 2.1–2.5 s for 15 % more factorization flops than
  // METIS. The order only changes round-off, not the solution (the stopping test is on the residual).
  int nestedDissectionMin = 300000;
  // Optional: share the factor with other solves (makeFlowSolverCache). Dirichlet vertices then stay unknowns with
  // identity rows, so that changes of the Dirichlet set keep the dimension. Ignored for circle loops.
  std::shared_ptr<FlowSolverCache> solverCache;
  // Armijo constant on the merit ½|r|² and the smallest step before giving up.
  double armijo = 1e-4;
  double minStep = 1e-12;
  // Delaunay tolerance of the Penner flips (see pennerDelaunayMargin): 1e-12 leaves cocircular quads alone.
  double delaunayTolerance = 1e-12;
  // Return a solution that contains faces with extended angles (π, 0, 0) instead of throwing; the genus-0
  // construction repairs them by flipping edges of the puncture's star and solving again.
  bool allowDegenerateFaces = false;
  // With allowDegenerateFaces: return early (RicciFlowReport::stoppedAtDegenerate) as soon as the full Newton step is
  // rejected while some face has the extended angles (π, 0, 0). Near such faces the energy is only C¹, Newton steps
  // are poor, and the genus-0 caller can repair the face by a flip of the puncture's star and solve again (measured:
  // 4 Newton steps of step length 0.03–0.002 at residual 1.3·10⁻³ on a 10⁵-vertex sphere otherwise; returning at the
  // first rejected step instead of below step length 1/16 saves one more Newton step and four trials there).
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
};

// Checks the target (sizes, finite, Θ̂ > 0 at free vertices, Gauss–Bonnet for closed Euclidean problems without frozen
// faces, positive area for hyperbolic ones) — throwing InputError naming the vertex or the imbalance — then runs
// Newton from the current u. Throws ConvergenceError with the residual reached when the step cap is hit or the line
// search stalls.
RicciFlowReport solveConformalFlow(DiscreteConformalMetric& metric, const ConformalTarget& target,
                                   const RicciFlowOptions& options = {}, FlowCorrespondence* log = nullptr);

// Per vertex: Σ of corner angles over the non-frozen faces at the current u (valid Delaunay state assumed).
std::vector<double> flowAngleSums(const DiscreteConformalMetric& metric);

}  // namespace conformesh::intrinsic
