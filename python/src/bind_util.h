// bind_util.h — what every part of the binding shares: NumPy array conversion (validated, named in errors, copied
// only when the library needs its own vector), nlohmann::json → Python objects, and the guard that lets long library
// calls run with the GIL released while progress callbacks and Ctrl-C are served between steps.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace conformesh::python {

namespace py = pybind11;

// An output that failed its verification (refine/pipeline/output_verification.h): conformesh.VerificationError, a
// RuntimeError; the CLI's exit 3.
struct VerificationFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Raises conformesh.InputError (a ValueError) with `message`.
[[noreturn]] void inputError(const std::string& message);

// An (n, 3) array of vertex indices: any integer dtype, any strides. Throws InputError naming `what` for a bad
// dtype, shape or a negative index; indices beyond `nVertices` (when ≥ 0) too.
std::vector<std::array<int, 3>> facesFromArray(const py::handle& obj, const std::string& what);
// An (n, k) array of finite reals (float or integer dtype, any strides), read row by row; k = `cols`.
// Throws InputError naming `what`, the row and the column for NaN/inf, a bad dtype or shape.
std::vector<double> realsFromArray(const py::handle& obj, const std::string& what, int cols, py::ssize_t* rows);
std::vector<Eigen::Vector3d> pointsFromArray(const py::handle& obj, const std::string& what);
// A 1-D array of n finite reals.
std::vector<double> vectorFromArray(const py::handle& obj, const std::string& what, py::ssize_t n);

// NumPy arrays that take ownership of the vector's buffer (no copy).
py::array_t<double> toArray(std::vector<double>&& v);
py::array_t<double> toArray(std::vector<double>&& v, py::ssize_t cols);
py::array_t<double> toArray(std::vector<Eigen::Vector3d>&& v);
py::array_t<double> toArray(std::vector<Eigen::Vector2d>&& v);
py::array_t<std::int32_t> toArray(std::vector<int>&& v);
py::array_t<std::int32_t> toArray(std::vector<int>&& v, py::ssize_t cols);

py::object toPython(const nlohmann::json& j);

// A long library call's companion. Construct it (holding the GIL) with the user's `progress` (None or a callable
// taking one str), then release the GIL for the call. `step(message)` — wired into the library's progress callbacks —
// takes the GIL back on the calling thread only, calls `progress(message)`, and checks for pending signals: Ctrl-C
// raises KeyboardInterrupt there (py::error_already_set unwinds the library call, which writes nothing half-done).
class CallGuard {
 public:
  explicit CallGuard(py::object progress);
  void step(const std::string& message);
  std::function<void(const std::string&)> lineCallback();
  std::function<void(int, int)> countCallback(const std::string& what);

 private:
  std::thread::id owner_;
  py::object progress_;
};

}  // namespace conformesh::python
