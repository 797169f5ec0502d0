// bind_util.cpp — see bind_util.h.
#include "bind_util.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::python {

void inputError(const std::string& message) {
  throw InputError(message);
}

namespace {

py::array asArray(const py::handle& obj, const std::string& what) {
  if (obj.is_none()) inputError(what + ": expected an array, got None");
  py::array a = py::array::ensure(obj);
  if (!a) inputError(what + ": expected an array-like of numbers");
  return a;
}

std::string shapeString(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtypeName(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

void checkShape(const py::array& a, const std::string& what, int cols) {
  if (a.ndim() != 2 || a.shape(1) != cols)
    inputError(what + ": expected shape (n, " + std::to_string(cols) + "), got " + shapeString(a));
}

template <class T>
void readFaces(const py::array& a, std::vector<std::array<int, 3>>& out, const std::string& what) {
  const auto r = a.unchecked<T, 2>();
  for (py::ssize_t f = 0; f < r.shape(0); ++f)
    for (int k = 0; k < 3; ++k) {
      const T x = r(f, k);
      if (x < 0 || static_cast<std::int64_t>(x) > INT32_MAX)
        inputError(what + ": face " + std::to_string(f) + " has vertex index " + std::to_string((long long)x) +
                   " (expected 0 .. 2^31 - 1)");
      out[f][k] = static_cast<int>(x);
    }
}

template <class T>
void readReals(const py::array& a, std::vector<double>& out, const std::string& what, const char* row) {
  const auto r = a.unchecked<T, 2>();
  const py::ssize_t cols = r.shape(1);
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (py::ssize_t k = 0; k < cols; ++k) {
      const double x = static_cast<double>(r(i, k));
      if (!std::isfinite(x))
        inputError(what + ": " + row + " " + std::to_string(i) + ", column " + std::to_string(k) + " is " +
                   formatNumber(x) + " (expected a finite number)");
      out[i * cols + k] = x;
    }
}

}  // namespace

std::vector<std::array<int, 3>> facesFromArray(const py::handle& obj, const std::string& what) {
  py::array a = asArray(obj, what);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    inputError(what + ": expected an integer array (int32 or int64), got dtype " + dtypeName(a));
  checkShape(a, what, 3);
  std::vector<std::array<int, 3>> faces(a.shape(0));
  if (a.dtype().is(py::dtype::of<std::int32_t>()) || (kind == 'i' && a.itemsize() == 4))
    readFaces<std::int32_t>(a, faces, what);
  else if (kind == 'i' && a.itemsize() == 8)
    readFaces<std::int64_t>(a, faces, what);
  else
    readFaces<std::int64_t>(py::array_t<std::int64_t, py::array::forcecast>::ensure(a), faces, what);
  return faces;
}

std::vector<double> realsFromArray(const py::handle& obj, const std::string& what, int cols, py::ssize_t* rows) {
  py::array a = asArray(obj, what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    inputError(what + ": expected a real array (float64, float32 or integer), got dtype " + dtypeName(a));
  checkShape(a, what, cols);
  std::vector<double> out(static_cast<std::size_t>(a.shape(0)) * cols);
  const bool perFace = what.size() >= 3 && what.compare(what.size() - 3, 3, ": L") == 0;
  const char* row = perFace ? "face" : "row";
  if (kind == 'f' && a.itemsize() == 8)
    readReals<double>(a, out, what, row);
  else
    readReals<double>(py::array_t<double, py::array::forcecast>::ensure(a), out, what, row);
  if (rows) *rows = a.shape(0);
  return out;
}

std::vector<Eigen::Vector3d> pointsFromArray(const py::handle& obj, const std::string& what) {
  py::ssize_t n = 0;
  const std::vector<double> xyz = realsFromArray(obj, what, 3, &n);
  std::vector<Eigen::Vector3d> p(n);
  for (py::ssize_t i = 0; i < n; ++i) p[i] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  return p;
}

std::vector<double> vectorFromArray(const py::handle& obj, const std::string& what, py::ssize_t n) {
  py::array a = asArray(obj, what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    inputError(what + ": expected a real array, got dtype " + dtypeName(a));
  if (a.ndim() != 1 || (n >= 0 && a.shape(0) != n))
    inputError(what + ": expected shape (" + std::to_string(n) + ",), got " + shapeString(a));
  auto d = py::array_t<double, py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<1>();
  std::vector<double> out(r.shape(0));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    if (!std::isfinite(r(i)))
      inputError(what + ": entry " + std::to_string(i) + " is " + formatNumber(r(i)) + " (expected a finite number)");
    out[i] = r(i);
  }
  return out;
}

namespace {
template <class T, class V>
py::array_t<T> own(V&& v, std::vector<py::ssize_t> shape) {
  auto* heap = new V(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<V*>(p); });
  return py::array_t<T>(shape, reinterpret_cast<const T*>(heap->data()), owner);
}
}  // namespace

py::array_t<double> toArray(std::vector<double>&& v) {
  const auto n = static_cast<py::ssize_t>(v.size());
  return own<double>(std::move(v), {n});
}
py::array_t<double> toArray(std::vector<double>&& v, py::ssize_t cols) {
  const auto n = static_cast<py::ssize_t>(v.size()) / cols;
  return own<double>(std::move(v), {n, cols});
}
py::array_t<double> toArray(std::vector<Eigen::Vector3d>&& v) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  const auto n = static_cast<py::ssize_t>(v.size());
  return own<double>(std::move(v), {n, 3});
}
py::array_t<double> toArray(std::vector<Eigen::Vector2d>&& v) {
  static_assert(sizeof(Eigen::Vector2d) == 2 * sizeof(double));
  const auto n = static_cast<py::ssize_t>(v.size());
  return own<double>(std::move(v), {n, 2});
}
py::array_t<std::int32_t> toArray(std::vector<int>&& v) {
  const auto n = static_cast<py::ssize_t>(v.size());
  return own<std::int32_t>(std::move(v), {n});
}
py::array_t<std::int32_t> toArray(std::vector<int>&& v, py::ssize_t cols) {
  const auto n = static_cast<py::ssize_t>(v.size()) / cols;
  return own<std::int32_t>(std::move(v), {n, cols});
}

py::object toPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& x : j) l.append(toPython(x));
      return std::move(l);
    }
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = toPython(it.value());
      return std::move(d);
    }
    default: return py::none();
  }
}

CallGuard::CallGuard(py::object progress) : owner_(std::this_thread::get_id()), progress_(std::move(progress)) {
  if (!progress_.is_none() && !PyCallable_Check(progress_.ptr())) inputError("progress: expected a callable or None");
}

void CallGuard::step(const std::string& message) {
  if (std::this_thread::get_id() != owner_) return;  // worker threads never touch Python
  py::gil_scoped_acquire gil;
  if (!progress_.is_none()) progress_(message);
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

std::function<void(const std::string&)> CallGuard::lineCallback() {
  return [this](const std::string& s) { step(s); };
}

std::function<void(int, int)> CallGuard::countCallback(const std::string& what) {
  return [this, what](int done, int total) {
    step(what + ": " + std::to_string(done) + " of " + std::to_string(total));
  };
}

}  // namespace conformesh::python
