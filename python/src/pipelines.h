// pipelines.h — uniformize, remesh, refine, convergence, layout and embed on arrays.
#pragma once

#include "bind_util.h"

namespace conformesh::python {

void bindPipelines(py::module_& m);
void bindStudies(py::module_& m);
void bindRefineAndEmbed(py::module_& m);

}  // namespace conformesh::python
