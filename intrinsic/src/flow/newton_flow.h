// newton_flow.h — the Newton solver behind solveConformalFlow (ricci_flow.h), one object per solve, its steps named:
// validate the target → build the unknowns → (per Newton step) assemble → solve → line search → stopping tests.
// Private to the flow (ricci_flow.cpp). It changes only the metric's u and connectivity (Ptolemy flips, recorded in the
// correspondence log) and the solver cache it is given. Derivations: docs/ricci_flow.md §2 and §3.3.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "conformesh/intrinsic/flow/ricci_flow.h"
#include "flow/flow_solver_cache.h"

namespace conformesh::intrinsic {

class NewtonFlowSolver {
 public:
  // The arguments of solveConformalFlow; they must outlive the solver. `options` is assumed valid
  // (RicciFlowOptions::validate).
  NewtonFlowSolver(DiscreteConformalMetric& metric, const ConformalTarget& target, const RicciFlowOptions& options,
                   FlowCorrespondence* log);

  // Runs the flow from the current u; the contract of solveConformalFlow (throws InputError, ConvergenceError).
  RicciFlowReport run();

 private:
  // --- validate the target (InputError naming the vertex or the imbalance)
  void checkTargetShape() const;
  void markCircleVertices();
  void markActiveFaces();
  double checkConeAngles();  // returns Σ (2π or π) − Θ̂ over the free vertices
  void checkGaussBonnet(double targetCurvature) const;

  // --- build the unknowns
  void buildUnknowns();
  void pinGaugeVertex();
  void prepareCircleLoops();
  void chooseMoebiusGauge();

  // --- residual r = Θ̂ − Θ on the equations, at the current u
  void updateCircleTargets();
  double gaugeAngle(int k) const;
  void evaluateResidual(double& maxAbs, double& norm2);
  bool anyDegenerateFace() const;
  void activateGaugeRows();

  // --- first evaluation and solver set-up
  void start();

  // --- assemble and solve the Newton system
  Eigen::VectorXd symmetricNewtonStep();
  Eigen::VectorXd circleDomainNewtonStep();
  void assembleCircleJacobian(Eigen::MatrixXd& U, Eigen::MatrixXd& V);
  void addCircleLoopTerms(int i, Eigen::MatrixXd& U, Eigen::MatrixXd& V);
  Eigen::VectorXd solveCircleDomain(const Eigen::MatrixXd& U, const Eigen::MatrixXd& V);

  // --- line search (Armijo on the convex energy where it is defined, else on ½|r|²); returns the accepted step length
  double lineSearch(const Eigen::VectorXd& delta, NewtonStepInfo& info);
  bool tryStep(const std::vector<double>& u0, const Eigen::VectorXd& delta, double t, double norm2Old,
               NewtonStepInfo& info);
  // The energy test: Euclidean, no circle loops, and not the genus-0 construction (allowDegenerateFaces), whose star
  // repair takes a rejected full step as its signal (docs/ricci_flow.md §2 "The energy and the line search").
  bool usesEnergy() const { return bg_ == Background::Euclidean && !circles_ && !options_.allowDegenerateFaces; }
  double energyHere(double& magnitude) const;  // conformalEnergy at the last evaluated point (up to a constant)
  bool acceptByEnergy(double t, double newNorm2, double norm2Old);
  std::pair<int, double> worstResidual() const;  // (v, Θ̂_v − Θ_v) of the largest |Θ̂ − Θ| at the last point
  std::string worstVertex() const;  // "vertex v (Θ̂ − Θ = …)" at the last evaluated point
  void restoreStart(const std::vector<double>& u0);
  bool stopAtDegenerateStart(const std::vector<double>& u0);
  void checkCrawl(double t, double before);
  void switchOnGauge();
  void switchOnGaugeAtStall(const std::vector<double>& u0);
  bool polishInExtendedPrecision(const std::vector<double>& u0);  // true: converged in extended precision
  [[noreturn]] void throwStalled(const std::vector<double>& u0, const NewtonStepInfo& info);

  // --- stopping tests
  void checkStepCap() const;
  bool finishStep(const NewtonStepInfo& info, double t);  // true: the caller's stopAfterStep ended the flow
  RicciFlowReport finish();

  DiscreteConformalMetric& metric_;
  const ConformalTarget& target_;
  const RicciFlowOptions& options_;
  FlowCorrespondence* log_;
  const HalfedgeMesh& m_;
  const int nV_;
  const Background bg_;
  const bool circles_;
  std::chrono::steady_clock::time_point start_;

  // The target: per vertex Θ̂ (circle-loop entries follow the metric), which vertices lie on a circle loop or in a
  // non-frozen face.
  std::vector<double> targetSum_;
  std::vector<char> onCircle_, inActiveFace_;
  bool anyFrozen_ = false, anyFixed_ = false;

  RicciFlowReport report_;
  // Unknowns: index_[v] (−1: none), unknowns_[i] its vertex; identity rows (Dirichlet vertices kept as unknowns with
  // a shared cache); the vertices whose residual is checked.
  std::vector<int> index_, unknowns_;
  bool shared_ = false;
  std::vector<char> identityRow_;
  std::vector<int> equations_;
  int n_ = 0;
  Eigen::VectorXd r_;  // the residual on the unknowns

  // Circle loops: current sides and inscribed polygons; the Möbius gauge (docs/ricci_flow.md §3.3).
  std::vector<std::vector<double>> loopSides_;
  std::vector<InscribedPolygon> loopPolygons_;
  int gaugeLoop_ = -1, gaugeK_[3] = {0, 0, 0};
  int gaugeRow_[2] = {-1, -1};
  double gaugeTarget_[2] = {0, 0};
  double gaugeSwitch_ = 0;
  bool gaugeOn_ = false;
  int row0_ = -1, row1_ = -1;  // the active gauge rows (−1 while off)
  std::string circleFailure_;

  // Linear algebra: the solver (the shared cache's or a local one) and its arrays.
  FlowSolverCache local_;
  FlowSolverCache* solver_ = nullptr;
  FlowWorkspace* work_ = nullptr;
  int factorizationsBefore_ = 0, cgBefore_ = 0;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  std::vector<Eigen::Triplet<double>> triplets_;  // circle domains
  std::vector<int> faceIndex_;                    // symmetric problems: the unknown of each vertex as faces see it
  bool patternValid_ = false;

  double maxAbs_ = 0, norm2_ = 0;  // max |r| and |r|² at the current u
  int crawlSteps_ = 0;             // consecutive accepted steps of t < kCrawlStep (checkCrawl)
  double crawlFrom_ = 0;           // max |r| when they began
  // Energy line search: E, Σ|terms| and the slope rᵀδ at the step's start u0.
  double energy0_ = 0, slope0_ = 0;
};

}  // namespace conformesh::intrinsic
