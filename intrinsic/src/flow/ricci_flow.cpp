// ricci_flow.cpp — the public entry points of the Newton flow (ricci_flow.h): option checks, the inscribed polygon of a
// circle loop, the shared solver cache, angle sums, and solveConformalFlow, which runs a NewtonFlowSolver
// (newton_flow.h). See docs/ricci_flow.md.
#include "conformesh/intrinsic/flow/ricci_flow.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "flow/face_angles.h"
#include "flow/flow_solver_cache.h"
#include "flow/newton_flow.h"

namespace conformesh::intrinsic {

namespace {

// "name: expected <expected>, found <value>" in the manner of Ceres' IsValid.
std::string ricciFlowExpected(const char* name, const char* what, double found) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "RicciFlowOptions::" << name << ": expected " << what << ", found " << found;
  return msg.str();
}

}  // namespace

std::string RicciFlowOptions::validate() const {
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) return ricciFlowExpected("tolerance", "a finite value >= 0", tolerance);
  if (!(relativeFloor >= 0) || !std::isfinite(relativeFloor))
    return ricciFlowExpected("relativeFloor", "a finite value >= 0", relativeFloor);
  if (maxNewtonSteps < 0) return ricciFlowExpected("maxNewtonSteps", ">= 0", maxNewtonSteps);
  if (maxReuseIterations < 0) return ricciFlowExpected("maxReuseIterations", ">= 0", maxReuseIterations);
  if (nestedDissectionMin < 0) return ricciFlowExpected("nestedDissectionMin", ">= 0", nestedDissectionMin);
  if (!(armijo > 0 && armijo < 0.5)) return ricciFlowExpected("armijo", "0 < armijo < 0.5", armijo);
  if (!(minStep > 0 && minStep <= 1)) return ricciFlowExpected("minStep", "0 < minStep <= 1", minStep);
  if (!(maxTrialStep > 0)) return ricciFlowExpected("maxTrialStep", "> 0", maxTrialStep);
  if (!(delaunayTolerance >= 0) || !std::isfinite(delaunayTolerance))
    return ricciFlowExpected("delaunayTolerance", "a finite value >= 0", delaunayTolerance);
  return "";
}

// ℓ_m/2R above which the longest side's half-angle is computed as the complement of the others (asin's condition
// number 1/√(1 − x²) exceeds 7 there).
constexpr double kInscribedNearDiameter = 0.99;

InscribedPolygon inscribedPolygon(const std::vector<double>& sides, int loop) {
  const int n = static_cast<int>(sides.size());
  const int m = static_cast<int>(std::max_element(sides.begin(), sides.end()) - sides.begin());
  const double longest = sides[m];
  double perimeter = 0;
  for (double l : sides) perimeter += l;
  if (n < 3 || !(longest < perimeter - longest))
    throw ConvergenceError("boundary loop " + std::to_string(loop) +
                           " has a side at least as long as all others together; it cannot be inscribed in a circle");
  // Centre inside iff f(R) = Σ 2 asin(ℓ_j/2R) − 2π ≥ 0 at R = ℓ_max/2. Then f is convex and decreasing on
  // [ℓ_max/2, ∞) and Newton from R₀ = max(perimeter/2π, ℓ_max/2) (where f ≥ 0 since asin x ≥ x) increases
  // monotonically to the root. Otherwise the root of g(R) = Σ_{j≠m} asin(ℓ_j/2R) − asin(ℓ_m/2R), negative at ℓ_max/2
  // and positive for large R, is bracketed and bisected.
  auto f = [&](double R, double& df) {
    double s = 0;
    df = 0;
    for (double l : sides) {
      const double x = std::min(1.0, l / (2 * R));
      s += 2 * std::asin(x);
      df -= x < 1 ? 2 * x / (R * std::sqrt((1 - x) * (1 + x))) : 0;
    }
    return s - 2 * M_PI;
  };
  InscribedPolygon out;
  out.side.assign(n, 1);
  double df;
  if (f(0.5 * longest, df) >= 0 && !(perimeter / (2 * M_PI) > 0.5 * longest)) {
    // Newton would start at R = ℓ_max/2, where the longest side's dφ/dR is infinite (f above drops it) and the first
    // step overshoots the root: the radius of a rectangle's circle came out 12 % too large, so its targets were wrong
    // by 0.98 rad and the flow stalled. Bisect instead: f ≥ 0 at ℓ_max/2 and < 0 for large R.
    double lo = 0.5 * longest, hi = 0.5 * perimeter;
    while (f(hi, df) >= 0) hi *= 2;
    for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (f(mid, df) >= 0 ? lo : hi) = mid;
    }
    out.radius = 0.5 * (lo + hi);
  } else if (f(0.5 * longest, df) >= 0) {
    double R = std::max(perimeter / (2 * M_PI), 0.5 * longest);
    for (int it = 0; it < 100; ++it) {
      const double value = f(R, df);
      if (!(value > 0) || !(df < 0)) break;
      const double next = R - value / df;
      if (!(next > R * (1 + 1e-16))) break;
      R = next;
    }
    out.radius = R;
  } else {
    auto g = [&](double R) {
      double s = 0;
      for (int j = 0; j < n; ++j) s += (j == m ? -1 : 1) * std::asin(std::min(1.0, sides[j] / (2 * R)));
      return s;
    };
    double lo = 0.5 * longest, hi = longest;
    while (g(hi) < 0) hi *= 2;
    for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) < 0 ? lo : hi) = mid;
    }
    out.radius = 0.5 * (lo + hi);
    out.side[m] = -1;
  }
  out.halfAngle.resize(n);
  for (int j = 0; j < n; ++j) {
    const double a = std::asin(std::min(1.0, sides[j] / (2 * out.radius)));
    out.halfAngle[j] = out.side[j] > 0 ? a : M_PI - a;
  }
  // Near a diameter (x = ℓ_m/2R → 1, e.g. a right triangle's hypotenuse) asin amplifies the 10⁻¹⁶ relative error of R
  // to √ε ≈ 1.5·10⁻⁸ in φ_m, so the targets would miss Σ φ = π by that much and the flow stall there. The other sides
  // are well conditioned, and Σ φ_j = π holds on both branches, so φ_m is taken as their complement.
  if (longest / (2 * out.radius) > kInscribedNearDiameter) {
    double others = 0;
    for (int j = 0; j < n; ++j)
      if (j != m) others += out.halfAngle[j];
    out.halfAngle[m] = M_PI - others;
  }
  return out;
}

std::shared_ptr<FlowSolverCache> makeFlowSolverCache(int maxReuseIterations, int nestedDissectionMin) {
  return std::make_shared<FlowSolverCache>(maxReuseIterations, nestedDissectionMin);
}

std::vector<double> flowAngleSums(const DiscreteConformalMetric& metric) {
  std::vector<double> length, sums;
  std::vector<detail::FaceGeometry> faces;
  detail::evaluateFaces(metric, length, sums, faces);
  return sums;
}

RicciFlowReport solveConformalFlow(DiscreteConformalMetric& metric, const ConformalTarget& target,
                                   const RicciFlowOptions& options, FlowCorrespondence* log) {
  const std::string invalid = options.validate();
  if (!invalid.empty()) throw InputError(invalid);
  return NewtonFlowSolver(metric, target, options, log).run();
}

}  // namespace conformesh::intrinsic
