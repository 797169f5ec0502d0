// uniformization_support.h (private) — the small pieces every uniformization target shares: the reference Penner
// chords of the input, the flow options with progress lines, summing flow reports, and recording the total vertex
// scaling as λ and the correspondence's log scale. Used by uniformization.cpp and sphere_puncture.cpp only.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::intrinsic::detail {

// The Euclidean triangulation of `input`'s Penner chords (its own lengths when Euclidean): the reference metric
// c⁰ whose conformal class every flow works in.
IntrinsicTriangulation referencePenner(const IntrinsicTriangulation& input);

// options.flow, with onStep also printing one progress line per Newton step prefixed by `stage` (when
// options.progress is set; the caller's onStep still runs after it).
RicciFlowOptions withProgress(const UniformizationOptions& options, const std::string& stage);

// Adds one flow solve's counts to `report`; the residual and tolerance are those of the latest solve.
void accumulate(UniformizationReport& report, const RicciFlowReport& flow);

// Records the total vertex scaling w (per vertex, log of the length factor): out.lambda = −w, log.logScale = w, and
// moves `log` into out.correspondence.
void attachScale(Uniformization& out, const std::vector<double>& w, FlowCorrespondence& log);

}  // namespace conformesh::intrinsic::detail
