// pipelines.h — uniformize, remesh, refine, convergence, layout and embed on arrays.
#pragma once

#include <nlohmann/json.hpp>

#include "bind_util.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::python {

void bindPipelines(py::module_& m);
void bindStudies(py::module_& m);
void bindRefineAndEmbed(py::module_& m);

// The CLI's verification before exit 0 (output_verification.h), in the report as report['verification']; a failed
// check raises VerificationError (the CLI's exit 3) unless keep_failed=True, which returns the result as it is.
void verifyOrRaise(const refine::OutputVerification& check, bool keepFailed, nlohmann::json& report);

}  // namespace conformesh::python
