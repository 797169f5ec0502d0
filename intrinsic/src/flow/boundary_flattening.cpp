// boundary_flattening.cpp — the flat conformal metric of a topological disk that keeps its boundary lengths: discrete
// Ricci flow with Dirichlet u = 0 on the boundary and zero curvature inside (boundary_flattening.h). The discrete
// problem is the one of uniformization.cpp's targets with the boundary held instead of bent into a circle: the
// Springborn–Schröder–Pinkall energy restricted to the interior u is strictly convex, so the solution Newton with
// Ptolemy flips (ricci_flow.h) finds is the only one, and there is no gauge to fix.
#include "conformesh/intrinsic/flow/boundary_flattening.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"

namespace conformesh::intrinsic {

Uniformization flattenKeepingBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validateLengths(input, "flattenKeepingBoundary");
  const std::vector<ComponentTopology> components = input.mesh.components();
  if (components.size() != 1 || components[0].genus != 0 || components[0].boundaryLoops != 1) {
    std::ostringstream msg;
    msg << "flattenKeepingBoundary: the surface must be a topological disk (one component, genus 0, one boundary "
           "loop); found "
        << components.size() << " component(s)";
    if (!components.empty())
      msg << ", the first of genus " << components[0].genus << " with " << components[0].boundaryLoops
          << " boundary loop(s)";
    throw InputError(msg.str());
  }
  UniformizationReport report;
  report.target = UniformizationTarget::FlatKeepBoundary;
  report.genus = 0;
  report.boundaryLoops = 1;

  // Reference Penner lengths: the input's chords in its own background (lengths themselves when Euclidean).
  IntrinsicTriangulation reference;
  reference.mesh = input.mesh;
  reference.background = Background::Euclidean;
  reference.edgeLengths.resize(input.edgeLengths.size());
  for (std::size_t e = 0; e < input.edgeLengths.size(); ++e)
    reference.edgeLengths[e] = pennerFromLength(input.background, input.edgeLengths[e]);
  DiscreteConformalMetric metric(std::move(reference), Background::Euclidean);
  const HalfedgeMesh& m = metric.mesh();
  FlowCorrespondence log(m.nFaces());

  // Boundary vertices are held at u = 0, so every boundary edge keeps its chord length; the interior is flat.
  ConformalTarget target;
  target.angleSum.assign(m.nVertices(), 2 * M_PI);
  target.fixed.assign(m.nVertices(), 0);
  for (int v = 0; v < m.nVertices(); ++v)
    if (m.isBoundaryVertex(v)) target.fixed[v] = 1;

  RicciFlowOptions flow = options.flow;
  if (options.progress) {
    auto user = options.flow.onStep;
    auto progress = options.progress;
    flow.onStep = [user, progress](const NewtonStepInfo& info) {
      std::ostringstream line;
      line.precision(3);
      line << "flat, boundary kept: Newton step " << info.step << ", max |K - K^| = " << info.maxResidual
           << " rad, step length " << info.stepLength << ", flips " << info.flips;
      progress(line.str());
      if (user) user(info);
    };
  }
  const RicciFlowReport solved = solveConformalFlow(metric, target, flow, &log);
  report.newtonSteps = solved.newtonSteps;
  report.flips = solved.flips;
  report.maxResidual = solved.maxResidual;
  report.effectiveTolerance = solved.effectiveTolerance;

  // λ = −w: the original metric is e^{2λ} × the flat one (uniformization.h); λ = 0 on the boundary.
  Uniformization out;
  out.uniform = metric.triangulation();
  out.lambda.resize(m.nVertices());
  for (int v = 0; v < m.nVertices(); ++v) out.lambda[v] = -metric.u()[v];
  log.logScale = metric.u();
  out.correspondence = std::move(log);
  const std::vector<Eigen::Vector2d> planar = layoutFlat(out.uniform);
  out.positions.resize(planar.size());
  for (std::size_t v = 0; v < planar.size(); ++v) out.positions[v] = Eigen::Vector3d(planar[v].x(), planar[v].y(), 0.0);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.report = report;
  return out;
}

}  // namespace conformesh::intrinsic
