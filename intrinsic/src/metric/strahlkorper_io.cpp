// strahlkorper_io.cpp — horizon shapes in HDF5 and as a sampled θ–φ radius (strahlkorper_io.h; layouts and node
// conventions in docs/horizons.md §2 and docs/formats.md).
#include "conformesh/intrinsic/metric/strahlkorper_io.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <Eigen/QR>
#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/spatial_metric_registry.h"
#include "metric/family_checks.h"
#include "metric/hdf5_handles.h"

namespace conformesh::intrinsic {

namespace {

using hdf5_detail::Id;
using metric_detail::fmt;

int strahlkorperYlmIndex(int l, int m) {
  return l * l + l + m;
}

[[noreturn]] void failAt(const std::string& source, const std::string& what) {
  throw InputError(describeAt(source, what));
}

// Caps before allocating: a horizon finder's grid is at most a few hundred nodes per direction.
constexpr hsize_t kMaxRows = 1u << 20;

}  // namespace

// ---------------------------------------------------------------------------------------------------------------------
// sampled radius

std::string toString(ThetaNodes n) {
  return n == ThetaNodes::GaussLegendre ? "gauss-legendre" : "uniform";
}
ThetaNodes parseThetaNodes(const std::string& s) {
  if (s == "gauss-legendre") return ThetaNodes::GaussLegendre;
  if (s == "uniform") return ThetaNodes::Uniform;
  throw InputError("unknown theta_nodes '" + s + "': expected gauss-legendre or uniform");
}
std::vector<double> thetaNodes(ThetaNodes kind, int n) {
  std::vector<double> theta(static_cast<size_t>(n));
  if (kind == ThetaNodes::Uniform) {
    for (int i = 0; i < n; ++i) theta[i] = M_PI * (i + 0.5) / n;
    return theta;
  }
  std::vector<double> x, w;
  gaussLegendre(n, x, w);
  for (int i = 0; i < n; ++i) theta[i] = std::acos(x[i]);  // the roots are symmetric: sorting pairs θ_i with w_i
  std::sort(theta.begin(), theta.end());
  return theta;
}
int defaultSampledLMax(int nTheta, int nPhi) {
  return std::min(nTheta - 1, (nPhi - 1) / 2);
}

namespace {

void checkSamples(const SampledRadius& s, const std::string& source, const std::vector<double>& theta) {
  const int nt = static_cast<int>(s.r.rows()), np = static_cast<int>(s.r.cols());
  if (nt < 2 || np < 3)
    throw InputError(describeAt(source, "the sampled radius needs at least 2 theta x 3 phi nodes, found " +
                                            std::to_string(nt) + " x " + std::to_string(np)));
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k)
      if (!std::isfinite(s.r(i, k)) || !(s.r(i, k) > 0))
        throw InputError(describeAt(source, "radius[" + std::to_string(i) + "][" + std::to_string(k) +
                                                "]: expected a finite positive number, found " + fmt(s.r(i, k)) +
                                                " (theta=" + fmt(theta[i]) + " phi=" + fmt(2 * M_PI * k / np) + ")"));
}

// The real Y_lm (l ≤ lMax) at every node, one row per node (i·nφ + k), one column per l² + l + m.
Eigen::MatrixXd ylmMatrix(const std::vector<double>& theta, int np, int lMax) {
  const int nt = static_cast<int>(theta.size()), nc = (lMax + 1) * (lMax + 1);
  Eigen::MatrixXd Y(nt * np, nc);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) {
      const std::vector<YlmJet> y = realYlmJets(lMax, theta[i], 2 * M_PI * k / np);
      for (int n = 0; n < nc; ++n) Y(i * np + k, n) = y[n].y;
    }
  return Y;
}

}  // namespace

RadiusFit fitSampledRadius(const SampledRadius& s, int lMax, const std::string& source) {
  const int nt = static_cast<int>(s.r.rows()), np = static_cast<int>(s.r.cols());
  const std::vector<double> theta = thetaNodes(s.nodes, std::max(nt, 1));
  checkSamples(s, source, theta);
  const int lDefault = defaultSampledLMax(nt, np);
  if (lMax < 0) lMax = s.lMax >= 0 ? s.lMax : lDefault;
  if (lMax > lDefault)
    throw InputError(describeAt(source, "l_max " + std::to_string(lMax) + " is too large for a " + std::to_string(nt) +
                                            " x " + std::to_string(np) + " grid: expected at most min(ntheta - 1, " +
                                            "(nphi - 1)/2) = " + std::to_string(lDefault)));
  const Eigen::MatrixXd Y = ylmMatrix(theta, np, lMax);
  Eigen::VectorXd r(nt * np);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) r(i * np + k) = s.r(i, k);
  Eigen::VectorXd a;
  if (s.nodes == ThetaNodes::GaussLegendre) {  // a_lm = Σ w_i (2π/nφ) r_ik Y_lm(θ_i, φ_k)
    std::vector<double> x, w;
    gaussLegendre(nt, x, w);
    Eigen::VectorXd wr(nt * np);
    for (int i = 0; i < nt; ++i)  // θ_i increasing ↔ x decreasing; the weights are symmetric
      for (int k = 0; k < np; ++k) wr(i * np + k) = w[i] * 2 * M_PI / np * r(i * np + k);
    a = Y.transpose() * wr;
  } else {
    a = Y.householderQr().solve(r);
  }
  RadiusFit fit;
  fit.lMax = lMax, fit.nodes = s.nodes, fit.nTheta = nt, fit.nPhi = np;
  const Eigen::VectorXd residual = Y * a - r;
  fit.maxResidual = residual.cwiseAbs().maxCoeff();
  fit.rmsResidual = std::sqrt(residual.squaredNorm() / residual.size());
  std::vector<Strahlkorper::Term> terms;
  for (int l = 0; l <= lMax; ++l)
    for (int m = -l; m <= l; ++m)
      if (l == 0 || std::abs(a(strahlkorperYlmIndex(l, m))) > 1e-15 * std::abs(a(0))) terms.push_back({l, m, a(strahlkorperYlmIndex(l, m))});
  fit.shape = Strahlkorper(s.center, terms);
  checkPositiveRadius(fit.shape, source);
  return fit;
}

SampledRadius sampleStrahlkorper(const Strahlkorper& shape, ThetaNodes nodes, int nTheta, int nPhi) {
  SampledRadius s;
  s.center = shape.center();
  s.nodes = nodes;
  s.r.resize(nTheta, nPhi);
  const std::vector<double> theta = thetaNodes(nodes, nTheta);
  for (int i = 0; i < nTheta; ++i)
    for (int k = 0; k < nPhi; ++k) s.r(i, k) = shape.radius(theta[i], 2 * M_PI * k / nPhi).r;
  return s;
}

// ---------------------------------------------------------------------------------------------------------------------
// HDF5 reading

namespace {

struct Array2 {
  hsize_t rows = 0, cols = 0;
  std::vector<double> v;  // row-major
};

// A numeric dataset of rank 1 (as 1 × n) or 2, read as float64.
Array2 readArray(hid_t group, const char* name, const std::string& where) {
  const std::string at = where + ": dataset '" + name + "'";
  Id d(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  if (!d.valid()) throw InputError(at + " is not a dataset");
  Id type(H5Dget_type(d.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(type.get());
  if (c != H5T_FLOAT && c != H5T_INTEGER) throw InputError(at + " must hold numbers");
  Id space(H5Dget_space(d.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != 1 && rank != 2) throw InputError(at + " must be 2-D, found rank " + std::to_string(rank));
  hsize_t dims[2] = {1, 1};
  H5Sget_simple_extent_dims(space.get(), rank == 1 ? dims + 1 : dims, nullptr);
  if (dims[0] > kMaxRows || dims[1] > kMaxRows || dims[0] * dims[1] > kMaxRows)
    throw InputError(at + " is too large (more than 2^20 values)");
  Array2 out{dims[0], dims[1], std::vector<double>(dims[0] * dims[1])};
  if (!out.v.empty() && H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.v.data()) < 0)
    throw InputError(at + ": cannot read as float64 (corrupt or truncated file?)");
  return out;
}

std::optional<std::vector<double>> numberAttribute(hid_t obj, const char* name, const std::string& where) {
  if (H5Aexists(obj, name) <= 0) return std::nullopt;
  Id a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Id type(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(type.get());
  if (c != H5T_FLOAT && c != H5T_INTEGER) throw InputError(where + ": attribute '" + name + "' must hold numbers");
  Id space(H5Aget_space(a.get()), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  std::vector<double> x(static_cast<size_t>(std::max<hssize_t>(n, 0)));
  if (n > 0 && H5Aread(a.get(), H5T_NATIVE_DOUBLE, x.data()) < 0)
    throw InputError(where + ": cannot read attribute '" + name + "' as float64");
  return x;
}

std::optional<double> scalarAttribute(hid_t obj, const char* name, const std::string& where) {
  const auto x = numberAttribute(obj, name, where);
  if (!x) return std::nullopt;
  if (x->size() != 1 || !std::isfinite((*x)[0]))
    throw InputError(where + ": attribute '" + name + "': expected one finite number, found " +
                     (x->size() != 1 ? std::to_string(x->size()) + " values" : fmt((*x)[0])));
  return (*x)[0];
}

std::optional<std::string> stringAttribute(hid_t obj, const char* name, const std::string& where) {
  if (H5Aexists(obj, name) <= 0) return std::nullopt;
  Id a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Id type(H5Aget_type(a.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) throw InputError(where + ": attribute '" + name + "' must be a string");
  Id mem(H5Tcopy(H5T_C_S1), H5Tclose);
  std::string s;
  if (H5Tis_variable_str(type.get()) > 0) {  // h5py's default
    H5Tset_size(mem.get(), H5T_VARIABLE);
    char* p = nullptr;
    if (H5Aread(a.get(), mem.get(), &p) < 0) throw InputError(where + ": cannot read attribute '" + name + "'");
    s = p ? p : "";
    H5free_memory(p);
  } else {
    const size_t n = H5Tget_size(type.get());
    H5Tset_size(mem.get(), n + 1);
    std::vector<char> b(n + 1, '\0');
    if (H5Aread(a.get(), mem.get(), b.data()) < 0) throw InputError(where + ": cannot read attribute '" + name + "'");
    s = b.data();
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();  // Fortran-style padding
  return s;
}

std::vector<std::string> attributeNames(hid_t obj) {
  std::vector<std::string> names;
  auto cb = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  hsize_t idx = 0;
  H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &idx, cb, &names);
  return names;
}

Eigen::Vector3d readCenter(hid_t g, const std::string& where) {
  std::vector<double> c;
  if (const auto a = numberAttribute(g, "center", where)) {
    c = *a;
  } else if (H5Lexists(g, "center", H5P_DEFAULT) > 0) {
    c = readArray(g, "center", where).v;
  } else {
    throw InputError(where + ": missing 'center' (an attribute or dataset of 3 numbers x, y, z)");
  }
  if (c.size() != 3)
    throw InputError(where + ": 'center': expected 3 numbers (x, y, z), found " + std::to_string(c.size()));
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c[i])) throw InputError(where + ": 'center'[" + std::to_string(i) + "] is " + fmt(c[i]));
  return Eigen::Vector3d(c[0], c[1], c[2]);
}

std::vector<Strahlkorper::Term> readCoefficients(hid_t g, const std::string& where, YlmConvention convention) {
  const Array2 a = readArray(g, "coefficients", where);
  const std::string at = where + ": dataset 'coefficients'";
  if (a.cols != 3 || a.rows == 0)
    throw InputError(at + ": expected shape (n, 3) with rows (l, m, a_lm), found (" + std::to_string(a.rows) + ", " +
                     std::to_string(a.cols) + ")");
  std::vector<Strahlkorper::Term> terms;
  for (hsize_t i = 0; i < a.rows; ++i) {
    const double l = a.v[3 * i], m = a.v[3 * i + 1], c = a.v[3 * i + 2];
    const std::string row = at + " row " + std::to_string(i);
    if (!(l >= 0 && l <= 1000 && l == std::floor(l)) || !(std::abs(m) <= l && m == std::floor(m)))
      throw InputError(row + ": expected integers l >= 0 (at most 1000) and |m| <= l, found l=" + fmt(l) +
                       " m=" + fmt(m));
    if (!std::isfinite(c)) throw InputError(row + ": a_lm is " + fmt(c) + " (expected a finite number)");
    const int li = static_cast<int>(l), mi = static_cast<int>(m);
    terms.push_back({li, mi, ylmConventionFactor(convention, mi) * c});
  }
  return terms;
}

RadiusFit readSampled(hid_t g, const std::string& where, const Eigen::Vector3d& center) {
  const Array2 a = readArray(g, "radius", where);
  SampledRadius s;
  s.center = center;
  if (const auto n = stringAttribute(g, "theta_nodes", where)) {
    try {
      s.nodes = parseThetaNodes(*n);
    } catch (const InputError& e) {
      throw InputError(where + ": attribute 'theta_nodes': " + e.what());
    }
  }
  s.r.resize(static_cast<Eigen::Index>(a.rows), static_cast<Eigen::Index>(a.cols));
  for (hsize_t i = 0; i < a.rows; ++i)
    for (hsize_t k = 0; k < a.cols; ++k) s.r(i, k) = a.v[i * a.cols + k];
  int lMax = -1;
  if (const auto l = scalarAttribute(g, "l_max", where)) {
    if (*l < 0 || *l != std::floor(*l)) throw InputError(where + ": attribute 'l_max': expected an integer >= 0");
    lMax = static_cast<int>(*l);
  }
  s.lMax = lMax;
  return fitSampledRadius(s, -1, where + ": dataset 'radius'");
}

HorizonFileMetadata readMetadata(hid_t g, const std::string& where, const std::string& path) {
  HorizonFileMetadata m;
  if (const auto t = scalarAttribute(g, "time", where)) m.hasTime = true, m.time = *t;
  if (const auto s = stringAttribute(g, "spatial_metric", where)) {
    m.spatialMetric = *s;
    const std::string file = s->substr(0, s->find(":/"));
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (file.find('.') != std::string::npos && std::filesystem::path(file).is_relative() &&
        std::filesystem::exists(folder / file))
      m.spatialMetric = (folder / *s).string();
  }
  for (const std::string& name : attributeNames(g))
    if (name.rfind("param_", 0) == 0 && name.size() > 6)
      m.params[name.substr(6)] = *scalarAttribute(g, name.c_str(), where);
  return m;
}

// Opens FILE (checked to be HDF5) and its group; `where` names them as "FILE:/group".
struct OpenGroup {
  std::optional<Id> file, group;
  std::string where;
};
OpenGroup openGroup(const std::string& path, const std::string& groupName) {
  if (!std::ifstream(path)) throw InputError(path + ": cannot open the horizon shape file");
  if (!isHdf5File(path)) throw InputError(path + ": not an HDF5 file (no HDF5 signature at its start)");
  OpenGroup o;
  o.file.emplace(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!o.file->valid()) throw InputError(path + ": cannot open as HDF5 (corrupt or truncated file?)");
  o.where = path + ":" + groupName;
  if (groupName != "/" && H5Lexists(o.file->get(), groupName.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(path + ": no group '" + groupName + "'");
  o.group.emplace(H5Gopen2(o.file->get(), groupName.c_str(), H5P_DEFAULT), H5Gclose);
  if (!o.group->valid()) throw InputError(o.where + ": not a group");
  return o;
}

}  // namespace

bool isHdf5ShapePath(const std::string& pathAndGroup) {
  const std::string path = hdf5_detail::splitGroup(pathAndGroup).first;
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".h5" || ext == ".hdf5" || ext == ".he5" || (std::ifstream(path) && isHdf5File(path));
}

HorizonShapeRecord readHorizonShapeHdf5(const std::string& pathAndGroup) {
  const auto [path, groupName] = hdf5_detail::splitGroup(pathAndGroup);
  const hdf5_detail::QuietErrors quiet;
  const OpenGroup o = openGroup(path, groupName);
  const hid_t g = o.group->get();
  HorizonShapeRecord rec;
  const Eigen::Vector3d center = readCenter(g, o.where);
  YlmConvention convention = YlmConvention::Orthonormal;
  if (const auto c = stringAttribute(g, "convention", o.where)) {
    try {
      convention = parseYlmConvention(*c);
    } catch (const InputError& e) {
      throw InputError(o.where + ": attribute 'convention': " + e.what());
    }
  }
  const bool coefficients = H5Lexists(g, "coefficients", H5P_DEFAULT) > 0;
  const bool radius = H5Lexists(g, "radius", H5P_DEFAULT) > 0;
  if (coefficients == radius)
    throw InputError(o.where + (coefficients ? ": both datasets 'coefficients' and 'radius'; give one"
                                             : ": missing dataset 'coefficients' (n x 3 rows l, m, a_lm) or 'radius' "
                                               "(ntheta x nphi)"));
  if (coefficients) {
    try {
      rec.shape = Strahlkorper(center, readCoefficients(g, o.where, convention));
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.rfind(o.where, 0) == 0 ? what : o.where + ": dataset 'coefficients': " + what);
    }
    checkPositiveRadius(rec.shape, o.where);
  } else {
    rec.sampled = true;
    rec.fit = readSampled(g, o.where, center);
    rec.shape = rec.fit.shape;
  }
  rec.meta = readMetadata(g, o.where, path);
  return rec;
}

namespace {

// A JSON shape file read once: its text (parseStrahlkorperJson takes text) and its parse.
struct JsonShapeFile {
  std::string text;
  nlohmann::json value;
};

JsonShapeFile readJsonShapeFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the horizon shape file");
  std::ostringstream ss;
  ss << in.rdbuf();
  JsonShapeFile f{ss.str(), {}};
  try {
    f.value = nlohmann::json::parse(f.text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not valid JSON: " + e.what());
  }
  return f;
}

HorizonFileMetadata metadataFromJson(const nlohmann::json& j, const std::string& shapePath);

}  // namespace

HorizonShapeRecord readHorizonShapeJson(const std::string& path) {
  const JsonShapeFile file = readJsonShapeFile(path);
  const nlohmann::json& j = file.value;
  HorizonShapeRecord rec;
  if (!j.is_object() || !j.contains("radius")) {
    rec.shape = parseStrahlkorperJson(file.text, path);
    rec.meta = metadataFromJson(j, path);
    return rec;
  }
  if (j.contains("coefficients")) throw InputError(path + ": both keys 'coefficients' and 'radius'; give one");
  const nlohmann::json& c = j.value("center", nlohmann::json());
  if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number())
    throw InputError(path + ": 'center': expected [x, y, z] (three numbers), found " + c.dump());
  SampledRadius s;
  s.center = Eigen::Vector3d(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
  if (j.contains("theta_nodes")) {
    if (!j["theta_nodes"].is_string()) throw InputError(path + ": 'theta_nodes': expected a string");
    try {
      s.nodes = parseThetaNodes(j["theta_nodes"].get<std::string>());
    } catch (const InputError& e) {
      throw InputError(path + ": 'theta_nodes': " + e.what());
    }
  }
  const nlohmann::json& r = j["radius"];
  if (!r.is_array() || r.empty() || !r[0].is_array())
    throw InputError(path + ": 'radius': expected a list of ntheta rows of nphi numbers");
  s.r.resize(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(r[0].size()));
  for (size_t i = 0; i < r.size(); ++i) {
    if (!r[i].is_array() || r[i].size() != r[0].size())
      throw InputError(path + ": radius[" + std::to_string(i) + "]: expected a row of " + std::to_string(r[0].size()) +
                       " numbers (as radius[0]), found " + r[i].dump().substr(0, 60));
    for (size_t k = 0; k < r[i].size(); ++k) {
      if (!r[i][k].is_number())
        throw InputError(path + ": radius[" + std::to_string(i) + "][" + std::to_string(k) +
                         "]: expected a number, found " + r[i][k].dump());
      s.r(i, k) = r[i][k].get<double>();
    }
  }
  int lMax = -1;
  if (j.contains("l_max")) {
    if (!j["l_max"].is_number_integer() || j["l_max"].get<int>() < 0)
      throw InputError(path + ": 'l_max': expected an integer >= 0, found " + j["l_max"].dump());
    lMax = j["l_max"].get<int>();
  }
  rec.sampled = true;
  rec.fit = fitSampledRadius(s, lMax, path);
  rec.shape = rec.fit.shape;
  rec.meta = metadataFromJson(j, path);
  return rec;
}

HorizonShapeRecord readHorizonShape(const std::string& pathAndGroup) {
  return isHdf5ShapePath(pathAndGroup) ? readHorizonShapeHdf5(pathAndGroup) : readHorizonShapeJson(pathAndGroup);
}

namespace {

bool marksShape(hid_t group) {
  for (const char* link : {"coefficients", "radius", "center"})
    if (H5Lexists(group, link, H5P_DEFAULT) > 0) return true;
  return H5Aexists(group, "center") > 0 || H5Aexists(group, "time") > 0;
}

void collectShapeGroups(hid_t group, const std::string& prefix, int depth, std::vector<std::string>& out) {
  if (marksShape(group)) out.push_back(prefix.empty() ? "/" : prefix);
  if (depth > 8) return;
  for (const std::string& name : hdf5_detail::linkNames(group)) {
    if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0) continue;
    Id g(H5Gopen2(group, name.c_str(), H5P_DEFAULT), H5Gclose);  // fails quietly for datasets
    if (g.valid()) collectShapeGroups(g.get(), prefix + "/" + name, depth + 1, out);
  }
}

}  // namespace

std::vector<std::string> listHorizonShapeGroups(const std::string& path) {
  const hdf5_detail::QuietErrors quiet;
  const OpenGroup o = openGroup(path, "/");
  std::vector<std::string> out;
  collectShapeGroups(o.group->get(), "", 0, out);
  return out;
}

bool hdf5GroupHoldsShape(const std::string& pathAndGroup) {
  const auto [path, groupName] = hdf5_detail::splitGroup(pathAndGroup);
  const hdf5_detail::QuietErrors quiet;
  if (!std::ifstream(path) || !isHdf5File(path)) return false;
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid() || (groupName != "/" && H5Lexists(file.get(), groupName.c_str(), H5P_DEFAULT) <= 0)) return false;
  Id group(H5Gopen2(file.get(), groupName.c_str(), H5P_DEFAULT), H5Gclose);
  return group.valid() && marksShape(group.get());
}

// ---------------------------------------------------------------------------------------------------------------------
// HDF5 writing

namespace {

void writeDoubles(hid_t obj, const char* name, const std::vector<double>& v, std::vector<hsize_t> dims, bool dataset,
                  const std::string& where) {
  Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (dataset) {
    Id d(H5Dcreate2(obj, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (!d.valid() || H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      throw InputError(where + ": cannot write dataset '" + name + "'");
    return;
  }
  Id a(H5Acreate2(obj, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, v.data()) < 0)
    throw InputError(where + ": cannot write attribute '" + name + "'");
}

void writeString(hid_t obj, const char* name, const std::string& s, const std::string& where) {
  Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<size_t>(s.size(), 1));
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id a(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  std::string b = s.empty() ? std::string(1, '\0') : s;
  if (!a.valid() || H5Awrite(a.get(), type.get(), b.data()) < 0)
    throw InputError(where + ": cannot write attribute '" + name + "'");
}

void writeGroup(hid_t file, const HorizonShapeGroup& sg, const std::string& path) {
  const std::string where = path + ":" + sg.group;
  Id lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.get(), 1);
  Id g(sg.group == "/" ? H5Gopen2(file, "/", H5P_DEFAULT)
                       : H5Gcreate2(file, sg.group.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
       H5Gclose);
  if (!g.valid()) throw InputError(where + ": cannot create the group");
  const HorizonShapeRecord& r = sg.record;
  const Eigen::Vector3d c = r.sampled ? sg.samples.center : r.shape.center();
  writeDoubles(g.get(), "center", {c.x(), c.y(), c.z()}, {3}, false, where);
  if (r.sampled) {
    const Eigen::MatrixXd& m = sg.samples.r;
    std::vector<double> v(static_cast<size_t>(m.size()));
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index k = 0; k < m.cols(); ++k) v[i * m.cols() + k] = m(i, k);
    writeDoubles(g.get(), "radius", v, {hsize_t(m.rows()), hsize_t(m.cols())}, true, where);
    writeString(g.get(), "theta_nodes", toString(sg.samples.nodes), where);
    if (sg.samples.lMax >= 0) writeDoubles(g.get(), "l_max", {double(sg.samples.lMax)}, {1}, false, where);
  } else {
    std::vector<double> v;
    for (const auto& t : r.shape.terms()) v.insert(v.end(), {double(t.l), double(t.m), t.a});
    writeDoubles(g.get(), "coefficients", v, {v.size() / 3, 3}, true, where);
    writeString(g.get(), "convention", "orthonormal", where);
  }
  if (r.meta.hasTime) writeDoubles(g.get(), "time", {r.meta.time}, {1}, false, where);
  writeString(g.get(), "spatial_metric", r.meta.spatialMetric, where);
  for (const auto& [k, v] : r.meta.params) writeDoubles(g.get(), ("param_" + k).c_str(), {v}, {1}, false, where);
}

}  // namespace

void writeHorizonShapesHdf5(const std::string& path, const std::vector<HorizonShapeGroup>& groups) {
  const hdf5_detail::QuietErrors quiet;
  const std::string temp = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  std::remove(temp.c_str());
  std::exception_ptr error;
  {
    Id file(H5Fcreate(temp.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!file.valid()) throw InputError(path + ": cannot create the HDF5 file");
    try {
      for (const HorizonShapeGroup& g : groups) writeGroup(file.get(), g, path);
      if (H5Fclose(file.release()) < 0) throw InputError(path + ": cannot write the HDF5 file");
    } catch (...) {
      error = std::current_exception();
    }
  }  // closed here on an error
  if (error) {
    std::remove(temp.c_str());
    std::rethrow_exception(error);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw InputError(path + ": cannot replace with the written file: " + std::strerror(errno));
  }
}

// ---------------------------------------------------------------------------------------------------------------------
// horizon_surface.h's file entry points, here so that they read every shape form

std::unique_ptr<HorizonSurfaceMetric> makeHorizonMetric(const std::string& shapePath, const std::string& spatialMetric,
                                                        const std::map<std::string, double>& params) {
  std::shared_ptr<const SpatialMetric> gamma = makeSpatialMetric(spatialMetric, params);
  return std::make_unique<HorizonSurfaceMetric>(readHorizonShape(shapePath).shape, std::move(gamma));
}

HorizonFileMetadata readHorizonMetadata(const std::string& shapePath) {
  if (isHdf5ShapePath(shapePath)) return readHorizonShapeHdf5(shapePath).meta;
  return metadataFromJson(readJsonShapeFile(shapePath).value, shapePath);
}

namespace {

// The keys beside the shape: spatial_metric (a relative file name resolved against the shape's folder), params, time.
HorizonFileMetadata metadataFromJson(const nlohmann::json& j, const std::string& shapePath) {
  HorizonFileMetadata m;
  if (!j.is_object()) failAt(shapePath, "expected a JSON object with keys center and coefficients");
  if (j.contains("spatial_metric")) {
    if (!j["spatial_metric"].is_string())
      failAt(shapePath, "'spatial_metric': expected a string, found " + j["spatial_metric"].dump());
    m.spatialMetric = j["spatial_metric"].get<std::string>();
    const std::string file = m.spatialMetric.substr(0, m.spatialMetric.find(":/"));
    const std::filesystem::path folder = std::filesystem::path(shapePath).parent_path();
    if (file.find('.') != std::string::npos && std::filesystem::path(file).is_relative() &&
        std::filesystem::exists(folder / file))
      m.spatialMetric = (folder / m.spatialMetric).string();
  }
  if (j.contains("params")) {
    if (!j["params"].is_object())
      failAt(shapePath, "'params': expected an object of numbers, found " + j["params"].dump());
    for (const auto& [k, v] : j["params"].items()) {
      if (!v.is_number()) failAt(shapePath, "'params." + k + "': expected a number, found " + v.dump());
      m.params[k] = v.get<double>();
    }
  }
  if (j.contains("time")) {
    if (!j["time"].is_number()) failAt(shapePath, "'time': expected a number, found " + j["time"].dump());
    m.hasTime = true, m.time = j["time"].get<double>();
  }
  return m;
}

}  // namespace

std::unique_ptr<HorizonSurfaceMetric> makeHorizonMetricFromFile(const std::string& shapePath) {
  const HorizonFileMetadata m = readHorizonMetadata(shapePath);
  try {
    return makeHorizonMetric(shapePath, m.spatialMetric, m.params);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.find(shapePath) != std::string::npos) throw;
    throw InputError(shapePath + ": " + what);
  }
}

}  // namespace conformesh::intrinsic
