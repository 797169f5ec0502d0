// sampled_field_hdf5.cpp — reading and writing sampled metric fields as HDF5 (see sampled_field_hdf5.h), through the
// HDF5 C library (Debian libhdf5-dev). HDF5's automatic error printing is switched off while we work: every failure
// becomes one InputError that names the file, group and object, instead of a stack dump on stderr.
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <vector>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"
#include "metric/hdf5_handles.h"

namespace conformesh::intrinsic {

namespace {

using hdf5_detail::Id;
using hdf5_detail::QuietErrors;
using hdf5_detail::splitGroup;

const char* const kFieldNames[3] = {"g_uu", "g_uv", "g_vv"};
// Guards the allocation before any sample is read: 10⁸ nodes (2.4 GB of float64) is far beyond any metric a mesher
// needs (the text format caps each axis at 10⁶).
constexpr long long kMaxNodes = 100'000'000;

std::string typeClassName(H5T_class_t c) {
  switch (c) {
    case H5T_INTEGER:
      return "integer";
    case H5T_FLOAT:
      return "floating point";
    case H5T_STRING:
      return "string";
    case H5T_ENUM:
      return "enum";
    case H5T_COMPOUND:
      return "compound";
    case H5T_ARRAY:
      return "array";
    default:
      return "another type";
  }
}

// =====================================================================================================================
// attributes

struct Reader {
  std::string where;  // "FILE" or "FILE:/group", prefix of every message
  hid_t group = -1;

  bool has(const char* name) const { return H5Aexists(group, name) > 0; }

  Id open(const char* name) const {
    if (!has(name))
      throw InputError(where + ": missing attribute '" + name +
                       "' (expected attributes chart, periodic_u, periodic_v and optionally poles)");
    Id a(H5Aopen(group, name, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw InputError(where + ": cannot open attribute '" + name + "'");
    return a;
  }

  std::vector<double> doubles(const char* name) const {
    Id a = open(name);
    Id type(H5Aget_type(a.get()), H5Tclose);
    const H5T_class_t c = H5Tget_class(type.get());
    if (c != H5T_FLOAT && c != H5T_INTEGER)
      throw InputError(where + ": attribute '" + name + "' must be numeric, found " + typeClassName(c));
    Id space(H5Aget_space(a.get()), H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n < 0 || n > 16) throw InputError(where + ": attribute '" + name + "' has an unreadable or too large shape");
    std::vector<double> x(static_cast<size_t>(n));
    if (n > 0 && H5Aread(a.get(), H5T_NATIVE_DOUBLE, x.data()) < 0)
      throw InputError(where + ": cannot read attribute '" + name + "' as float64");
    return x;
  }

  // An integer flag, 0 or 1: an integer attribute, or h5py's bool (an enum over int8).
  bool flag(const char* name) const {
    Id a = open(name);
    Id type(H5Aget_type(a.get()), H5Tclose);
    const H5T_class_t c = H5Tget_class(type.get());
    Id space(H5Aget_space(a.get()), H5Sclose);
    if (H5Sget_simple_extent_npoints(space.get()) != 1)
      throw InputError(where + ": attribute '" + name + "' must be a single value (0 or 1)");
    long long value = -1;
    if (c == H5T_INTEGER) {
      if (H5Aread(a.get(), H5T_NATIVE_LLONG, &value) < 0)
        throw InputError(where + ": cannot read attribute '" + name + "' as an integer");
    } else if (c == H5T_ENUM) {
      // Read in the file's own enum type: the bytes are the member's integer value.
      const size_t size = H5Tget_size(type.get());
      unsigned char bytes[8] = {0};
      Id mem(H5Tget_native_type(type.get(), H5T_DIR_ASCEND), H5Tclose);
      if (size > sizeof(bytes) || H5Aread(a.get(), mem.get(), bytes) < 0)
        throw InputError(where + ": cannot read attribute '" + name + "' (an enum)");
      long long v = 0;
      std::memcpy(&v, bytes, size);  // little-endian host; values 0 and 1 are what matters
      value = v;
    } else {
      throw InputError(where + ": attribute '" + name + "' must be an integer 0 or 1 (or a bool), found " +
                       typeClassName(c));
    }
    if (value != 0 && value != 1)
      throw InputError(where + ": attribute '" + name + "' must be 0 or 1, found " + std::to_string(value));
    return value == 1;
  }

  std::string text(const char* name) const {
    Id a = open(name);
    Id type(H5Aget_type(a.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING)
      throw InputError(where + ": attribute '" + name + "' must be a string, found " +
                       typeClassName(H5Tget_class(type.get())));
    std::string s;
    if (H5Tis_variable_str(type.get()) > 0) {
      Id mem(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(mem.get(), H5T_VARIABLE);
      H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
      char* p = nullptr;
      if (H5Aread(a.get(), mem.get(), &p) < 0 || !p) throw InputError(where + ": cannot read attribute '" + name + "'");
      s = p;
      H5free_memory(p);
    } else {
      const size_t size = H5Tget_size(type.get());
      std::vector<char> buf(size + 1, '\0');
      if (H5Aread(a.get(), type.get(), buf.data()) < 0)
        throw InputError(where + ": cannot read attribute '" + name + "'");
      s = buf.data();
    }
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();  // fixed-length space padding
    return s;
  }

  // One of the three datasets, as float64 in row-major order, with its (NV, NU) shape.
  std::vector<double> dataset(const char* name, hsize_t dims[2]) const {
    if (H5Lexists(group, name, H5P_DEFAULT) <= 0)
      throw InputError(where + ": missing dataset '" + name +
                       "' (expected datasets g_uu, g_uv, g_vv of shape (NV, NU))");
    Id d(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
    if (!d.valid()) throw InputError(where + ": '" + name + "' is not a dataset");
    Id type(H5Dget_type(d.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_FLOAT)
      throw InputError(where + ": dataset '" + name + "' must hold floating-point numbers, found " +
                       typeClassName(H5Tget_class(type.get())));
    Id space(H5Dget_space(d.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank != 2)
      throw InputError(where + ": dataset '" + name + "' must be 2-D with shape (NV, NU), found rank " +
                       std::to_string(rank));
    H5Sget_simple_extent_dims(space.get(), dims, nullptr);
    if (dims[0] == 0 || dims[1] == 0 || static_cast<double>(dims[0]) * static_cast<double>(dims[1]) > kMaxNodes)
      throw InputError(where + ": dataset '" + name + "' has shape (" + std::to_string(dims[0]) + ", " +
                       std::to_string(dims[1]) + "); expected 1 to " + std::to_string(kMaxNodes) + " nodes");
    std::vector<double> x(dims[0] * dims[1]);
    if (H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()) < 0)
      throw InputError(where + ": cannot read dataset '" + name + "' as float64 (corrupt or truncated file?)");
    return x;
  }
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw InputError(what);
}

}  // namespace

// =====================================================================================================================
// public functions

bool isHdf5File(const std::string& pathAndGroup) {
  static const unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  std::ifstream in(splitGroup(pathAndGroup).first, std::ios::binary);
  unsigned char head[8] = {0};
  return in.read(reinterpret_cast<char*>(head), 8) && std::memcmp(head, kSignature, 8) == 0;
}

SampledField readSampledFieldHdf5(const std::string& pathAndGroup) {
  const auto [path, groupName] = splitGroup(pathAndGroup);
  const QuietErrors quiet;
  if (!std::ifstream(path)) throw InputError(path + ": cannot open the metric field file");
  if (!isHdf5File(path)) throw InputError(path + ": not an HDF5 file (no HDF5 signature at its start)");
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path + ": cannot open as HDF5 (corrupt or truncated file?)");
  Reader r;
  r.where = groupName == "/" ? path : path + ":" + groupName;
  if (H5Lexists(file.get(), groupName.c_str(), H5P_DEFAULT) <= 0 && groupName != "/")
    throw InputError(path + ": no group '" + groupName + "'");
  Id group(H5Gopen2(file.get(), groupName.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw InputError(r.where + ": not a group");
  r.group = group.get();

  if (r.has("conformesh_metric_field")) {
    const std::vector<double> version = r.doubles("conformesh_metric_field");
    if (version.size() != 1 || version[0] != 1)
      throw InputError(r.where + ": attribute 'conformesh_metric_field' must be 1 (the format version)");
  }
  SampledField f;
  f.source = r.where;
  const std::vector<double> chart = r.doubles("chart");
  if (chart.size() != 4)
    throw InputError(r.where + ": attribute 'chart' must hold 4 numbers U0 U1 V0 V1, found " +
                     std::to_string(chart.size()));
  f.domain.u0 = chart[0], f.domain.u1 = chart[1], f.domain.v0 = chart[2], f.domain.v1 = chart[3];
  checkChartBounds(f.domain, r.where + ": attribute 'chart'");
  f.domain.periodicU = r.flag("periodic_u");
  f.domain.periodicV = r.flag("periodic_v");
  const std::string poles = r.has("poles") ? r.text("poles") : "none";
  if (poles != "none" && poles != "both")
    throw InputError(r.where + ": attribute 'poles' must be \"none\" or \"both\", found \"" + poles + "\"");

  std::vector<double>* out[3] = {&f.guu, &f.guv, &f.gvv};
  hsize_t shape[3][2];
  for (int k = 0; k < 3; ++k) *out[k] = r.dataset(kFieldNames[k], shape[k]);
  for (int k = 1; k < 3; ++k)
    if (shape[k][0] != shape[0][0] || shape[k][1] != shape[0][1])
      throw InputError(r.where + ": datasets g_uu and " + kFieldNames[k] + " differ in shape: (" +
                       std::to_string(shape[0][0]) + ", " + std::to_string(shape[0][1]) + ") and (" +
                       std::to_string(shape[k][0]) + ", " + std::to_string(shape[k][1]) + ")");
  f.nv = static_cast<int>(shape[0][0]), f.nu = static_cast<int>(shape[0][1]);
  for (int k = 0; k < 3; ++k)
    for (size_t n = 0; n < out[k]->size(); ++n)
      if (!std::isfinite((*out[k])[n]))
        throw InputError(r.where + ": dataset '" + kFieldNames[k] + "' [" + std::to_string(n / f.nu) + "][" +
                         std::to_string(n % f.nu) + "] (grid node " + std::to_string(n % f.nu) + ", " +
                         std::to_string(n / f.nu) + ") is " + formatNumber((*out[k])[n]) +
                         "; every sample must be finite");
  if (poles == "both") markPoleToPole(f, r.where);
  return f;
}

void writeSampledFieldHdf5(const SampledField& f, const std::string& path, const std::string& group) {
  const QuietErrors quiet;
  if (f.nu <= 0 || f.nv <= 0 || f.guu.size() != static_cast<size_t>(f.nu) * f.nv || f.guv.size() != f.guu.size() ||
      f.gvv.size() != f.guu.size())
    throw InputError(path + ": cannot write a field whose sample count is not NU x NV");
  hdf5_detail::NewFileGroup out(path, group);
  const std::string& where = out.where;
  const hid_t g = out.target();
  auto attribute = [&](const char* name, hid_t fileType, hid_t memType, hsize_t n, const void* data) {
    Id space(n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
    Id a(H5Acreate2(g, name, fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    check(a.valid() ? H5Awrite(a.get(), memType, data) : -1, where + ": cannot write attribute '" + name + "'");
  };
  const int version = 1, pu = f.domain.periodicU, pv = f.domain.periodicV;
  const double chart[4] = {f.domain.u0, f.domain.u1, f.domain.v0, f.domain.v1};
  attribute("conformesh_metric_field", H5T_STD_I32LE, H5T_NATIVE_INT, 1, &version);
  attribute("chart", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 4, chart);
  attribute("periodic_u", H5T_STD_I32LE, H5T_NATIVE_INT, 1, &pu);
  attribute("periodic_v", H5T_STD_I32LE, H5T_NATIVE_INT, 1, &pv);
  const std::string poles = f.domain.poleAtV0 ? "both" : "none";
  Id str(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(str.get(), poles.size());
  attribute("poles", str.get(), str.get(), 1, poles.c_str());
  const hsize_t dims[2] = {static_cast<hsize_t>(f.nv), static_cast<hsize_t>(f.nu)};
  const std::vector<double>* in[3] = {&f.guu, &f.guv, &f.gvv};
  for (int k = 0; k < 3; ++k) {
    Id space(H5Screate_simple(2, dims, nullptr), H5Sclose);
    Id d(H5Dcreate2(g, kFieldNames[k], H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    check(d.valid() ? H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, in[k]->data()) : -1,
          where + ": cannot write dataset '" + std::string(kFieldNames[k]) + "'");
  }
  out.commit();
}

}  // namespace conformesh::intrinsic
