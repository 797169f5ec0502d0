// uniformization_support.cpp — the pieces shared by the uniformization targets (uniformization_support.h).
#include "flow/uniformization_support.h"

#include <sstream>

#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic::detail {

IntrinsicTriangulation referencePenner(const IntrinsicTriangulation& input) {
  IntrinsicTriangulation ref;
  ref.mesh = input.mesh;
  ref.background = Background::Euclidean;
  ref.edgeLengths.resize(input.edgeLengths.size());
  for (std::size_t e = 0; e < input.edgeLengths.size(); ++e)
    ref.edgeLengths[e] = pennerFromLength(input.background, input.edgeLengths[e]);
  return ref;
}

RicciFlowOptions withProgress(const UniformizationOptions& options, const std::string& stage) {
  RicciFlowOptions flow = options.flow;
  if (options.progress) {
    auto user = options.flow.onStep;
    auto progress = options.progress;
    flow.onStep = [user, progress, stage](const NewtonStepInfo& info) {
      std::ostringstream line;
      line.precision(3);
      line << stage << ": Newton step " << info.step << ", max |K - K^| = " << info.maxResidual << " rad, step length "
           << info.stepLength << ", flips " << info.flips;
      progress(line.str());
      if (user) user(info);
    };
  }
  return flow;
}

void accumulate(UniformizationReport& report, const RicciFlowReport& flow) {
  report.newtonSteps += flow.newtonSteps;
  report.flips += flow.flips;
  report.factorizations += flow.factorizations;
  report.cgIterations += flow.cgIterations;
  report.maxResidual = flow.maxResidual;
  report.effectiveTolerance = flow.effectiveTolerance;
}

// Vertex scaling multiplies lengths by e^{(w_i+w_j)/2}, i.e. by e^{w} where w is constant: the uniform metric is
// e^{2w} × the original, so the original is e^{2λ} × the uniform one with λ = −w.
void attachScale(Uniformization& out, const std::vector<double>& w, FlowCorrespondence& log) {
  out.lambda.resize(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) out.lambda[i] = -w[i];
  log.logScale = w;
  out.correspondence = std::move(log);
}

}  // namespace conformesh::intrinsic::detail
