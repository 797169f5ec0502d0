// errors.h — the exception types conformesh throws, and how they name what went wrong.
//
// Every error a user can cause (bad file, bad mesh, bad parameter, a flow that does not converge) is reported by one of
// these, with a message that says where (file, line, element) and what was expected versus found. The CLI catches them,
// prints the message on one line and exits non-zero; library users catch them by type.
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>

namespace conformesh {

// Malformed or inadmissible input: a file that cannot be parsed, a mesh that is not a manifold, a length that is NaN.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An iterative method stopped without reaching its tolerance (Newton, flipping, refinement caps). `vertex()`: where a
// flow stopped worst (the vertex its message names), −1 when the error does not name one; the circle domains' boundary
// splits read it (docs/ricci_flow.md §3.3).
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ConvergenceError(const std::string& what, int vertex) : std::runtime_error(what), vertex_(vertex) {}
  int vertex() const { return vertex_; }

 private:
  int vertex_ = -1;
};

// Formats "where: what" with an optional source name, e.g. "mesh.obj:12: face 7 repeats vertex 3".
inline std::string describeAt(const std::string& source, const std::string& what) {
  return source.empty() ? what : source + ": " + what;
}

// A number as it should read in a message: the shortest form that reads back to the same double, so that a length or
// residual quoted in an error can be compared bit for bit with the file it came from.
inline std::string formatNumber(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace conformesh
