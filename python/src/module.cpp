// module.cpp — the extension conformesh._conformesh: exceptions, then the parts (python/conformesh/__init__.py
// re-exports them as the public package).
#include <pybind11/pybind11.h>

#include "bind_util.h"
#include "conformesh/intrinsic/errors.h"
#include "metrics.h"
#include "pipelines.h"
#include "triangulation.h"

PYBIND11_MODULE(_conformesh, m) {
  namespace py = pybind11;
  m.doc() = "conformesh's compiled core; use the package `conformesh`.";
  m.attr("__version__") = CONFORMESH_VERSION;
  py::register_exception<conformesh::InputError>(m, "InputError", PyExc_ValueError)
      .doc() = "Malformed or inadmissible input (a ValueError): the message names the file, line or element.";
  py::register_exception<conformesh::ConvergenceError>(m, "ConvergenceError", PyExc_RuntimeError)
      .doc() = "An iterative method stopped without reaching its tolerance (a RuntimeError).";
  py::register_exception<conformesh::python::VerificationFailed>(m, "VerificationError", PyExc_RuntimeError)
      .doc() = "An output failed its verification before being returned (a RuntimeError): the message names the "
               "element, expected against found.";
  conformesh::python::bindTriangulation(m);
  py::module_ metrics = m.def_submodule("metrics", "Smooth metrics: families, sampled fields.");
  conformesh::python::bindMetrics(metrics);
  conformesh::python::bindPipelines(m);
  conformesh::python::bindStudies(m);
  conformesh::python::bindRefineAndEmbed(m);
}
