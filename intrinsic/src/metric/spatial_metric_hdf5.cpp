// spatial_metric_hdf5.cpp — γ_ij on a Cartesian grid in HDF5: the ADMBase, CarpetIOHDF5 and SpECTRE dataset names
// and the origin/delta attributes of sampled_spatial_metric.h, through the HDF5 C library.
#include <algorithm>
#include <cctype>
#include <optional>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"
#include "metric/hdf5_handles.h"

namespace conformesh::intrinsic {

namespace {

using hdf5_detail::Id;

// Cap before allocating: 512³ nodes × 6 components × 8 bytes = 6.4 GB is beyond any horizon's neighbourhood.
constexpr double kMaxGridNodes = 512.0 * 512 * 512;

std::string lowerCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The six dataset names of the group: the ADMBase or SpECTRE names when one of them is present (then all six must
// be), else CarpetIOHDF5's "ADMBASE::gxx it=… tl=… rl=… c=…" (exactly one per component).
std::array<std::string, 6> componentDatasets(hid_t group, const std::string& where) {
  for (const char* naming : {"admbase", "spectre"}) {
    const auto& names = spatialMetricComponentNames(naming);
    const bool any = std::any_of(names.begin(), names.end(),
                                 [&](const std::string& n) { return H5Lexists(group, n.c_str(), H5P_DEFAULT) > 0; });
    if (!any) continue;
    for (const auto& n : names)
      if (H5Lexists(group, n.c_str(), H5P_DEFAULT) <= 0)
        throw InputError(where + ": missing dataset '" + n + "' (expected the six components " + names[0] + " ... " +
                         names[5] + ")");
    return names;
  }
  const auto& adm = spatialMetricComponentNames("admbase");
  const std::vector<std::string> links = hdf5_detail::linkNames(group);
  std::array<std::string, 6> found;
  for (int c = 0; c < 6; ++c) {
    const std::string prefix = "admbase::" + adm[c];
    std::vector<std::string> hits;
    for (const auto& l : links) {
      const std::string s = lowerCase(l);
      if (s.compare(0, prefix.size(), prefix) == 0 && (s.size() == prefix.size() || s[prefix.size()] == ' '))
        hits.push_back(l);
    }
    if (hits.empty())
      throw InputError(where + ": missing dataset '" + adm[c] + "' (expected gxx ... gzz, SpatialMetric_xx ... " +
                       "SpatialMetric_zz, or CarpetIOHDF5's 'ADMBASE::" + adm[c] + " it=...')");
    if (hits.size() > 1)
      throw InputError(where + ": " + std::to_string(hits.size()) + " datasets for " + adm[c] + " ('" + hits[0] +
                       "', '" + hits[1] + "', ...): several iterations, refinement levels or components; copy the " +
                       "one uniform grid wanted into its own group (h5copy) and read FILE.h5:/group");
    found[c] = hits[0];
  }
  return found;
}

std::optional<std::vector<double>> vectorAttribute(hid_t obj, const char* name, const std::string& where) {
  if (H5Aexists(obj, name) <= 0) return std::nullopt;
  Id a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Id type(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(type.get());
  Id space(H5Aget_space(a.get()), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if ((c != H5T_FLOAT && c != H5T_INTEGER) || n != 3)
    throw InputError(where + ": attribute '" + name + "' must hold 3 numbers (x, y, z), found " +
                     (c != H5T_FLOAT && c != H5T_INTEGER ? std::string("a non-numeric type")
                                                          : std::to_string(n) + " values"));
  std::vector<double> x(3);
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, x.data()) < 0)
    throw InputError(where + ": cannot read attribute '" + name + "' as float64");
  return x;
}

struct ComponentData {
  std::vector<double> values;
  hsize_t dims[3];
  std::optional<std::vector<double>> origin, delta;
};

ComponentData readComponent(hid_t group, const std::string& name, const std::string& where) {
  const std::string at = where + ": dataset '" + name + "'";
  Id d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.valid()) throw InputError(at + " is not a dataset");
  Id type(H5Dget_type(d.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_FLOAT) throw InputError(at + " must hold floating-point numbers");
  Id space(H5Dget_space(d.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != 3) throw InputError(at + " must be 3-D with shape (nz, ny, nx), found rank " + std::to_string(rank));
  ComponentData out;
  H5Sget_simple_extent_dims(space.get(), out.dims, nullptr);
  if (static_cast<double>(out.dims[0]) * out.dims[1] * out.dims[2] > kMaxGridNodes)
    throw InputError(at + " has more than 512^3 nodes");
  out.values.resize(out.dims[0] * out.dims[1] * out.dims[2]);
  if (!out.values.empty() && H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()) < 0)
    throw InputError(at + ": cannot read as float64 (corrupt or truncated file?)");
  out.origin = vectorAttribute(d.get(), "origin", at);
  out.delta = vectorAttribute(d.get(), "delta", at);
  return out;
}

std::string shapeText(const hsize_t d[3]) {
  return "(" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + ", " + std::to_string(d[2]) + ")";
}

// origin or delta: the dataset's own attribute, else the group's; the same for all six.
Eigen::Vector3d gridAttribute(const std::array<ComponentData, 6>& comp, const std::array<std::string, 6>& names,
                              hid_t group, const char* which, const std::string& where) {
  const auto fromGroup = vectorAttribute(group, which, where);
  std::optional<std::vector<double>> value;
  for (int c = 0; c < 6; ++c) {
    const auto& mine = std::string(which) == "origin" ? comp[c].origin : comp[c].delta;
    const auto v = mine ? mine : fromGroup;
    if (!v)
      throw InputError(where + ": no attribute '" + which + "' on dataset '" + names[c] + "' nor on the group");
    if (value && *value != *v)
      throw InputError(where + ": attribute '" + which + "' of dataset '" + names[c] + "' differs from that of '" +
                       names[0] + "'");
    value = v;
  }
  return Eigen::Vector3d((*value)[0], (*value)[1], (*value)[2]);
}

}  // namespace

SpatialMetricGrid readSpatialMetricHdf5(const std::string& pathAndGroup) {
  const auto [path, groupName] = hdf5_detail::splitGroup(pathAndGroup);
  const hdf5_detail::QuietErrors quiet;
  if (!std::ifstream(path)) throw InputError(path + ": cannot open the spatial metric file");
  if (!isHdf5File(path)) throw InputError(path + ": not an HDF5 file (no HDF5 signature at its start)");
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path + ": cannot open as HDF5 (corrupt or truncated file?)");
  const std::string where = groupName == "/" ? path : path + ":" + groupName;
  if (groupName != "/" && H5Lexists(file.get(), groupName.c_str(), H5P_DEFAULT) <= 0)
    throw InputError(path + ": no group '" + groupName + "'");
  Id group(H5Gopen2(file.get(), groupName.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw InputError(where + ": not a group");

  const std::array<std::string, 6> names = componentDatasets(group.get(), where);
  std::array<ComponentData, 6> comp;
  for (int c = 0; c < 6; ++c) {
    comp[c] = readComponent(group.get(), names[c], where);
    if (c > 0 && !std::equal(comp[c].dims, comp[c].dims + 3, comp[0].dims))
      throw InputError(where + ": datasets '" + names[0] + "' and '" + names[c] + "' differ in shape: " +
                       shapeText(comp[0].dims) + " and " + shapeText(comp[c].dims) + " (all six must be (nz, ny, nx))");
  }
  SpatialMetricGrid g;
  g.source = where;
  g.n = {static_cast<int>(comp[0].dims[2]), static_cast<int>(comp[0].dims[1]), static_cast<int>(comp[0].dims[0])};
  g.origin = gridAttribute(comp, names, group.get(), "origin", where);
  g.delta = gridAttribute(comp, names, group.get(), "delta", where);
  for (int c = 0; c < 6; ++c) g.g[c] = std::move(comp[c].values), g.datasets[c] = names[c];
  checkSpatialMetricGrid(g);
  return g;
}

void writeSpatialMetricHdf5(const SpatialMetricGrid& g, const std::string& path, const std::string& group,
                            const std::string& naming) {
  const auto& names = spatialMetricComponentNames(naming);
  const hdf5_detail::QuietErrors quiet;
  hdf5_detail::NewFileGroup out(path, group);
  const std::string& where = out.where;
  const hid_t target = out.target();
  auto attributes = [&](hid_t obj) {
    for (const auto& [name, v] : {std::pair<const char*, Eigen::Vector3d>{"origin", g.origin}, {"delta", g.delta}}) {
      const hsize_t three = 3;
      Id space(H5Screate_simple(1, &three, nullptr), H5Sclose);
      Id a(H5Acreate2(obj, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
      if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, v.data()) < 0)
        throw InputError(where + ": cannot write attribute '" + name + "'");
    }
  };
  attributes(target);
  const hsize_t dims[3] = {static_cast<hsize_t>(g.n[2]), static_cast<hsize_t>(g.n[1]), static_cast<hsize_t>(g.n[0])};
  for (int c = 0; c < 6; ++c) {
    if (g.g[c].size() != dims[0] * dims[1] * dims[2])
      throw InputError(where + ": component " + names[c] + " has the wrong sample count for its grid");
    Id space(H5Screate_simple(3, dims, nullptr), H5Sclose);
    Id d(H5Dcreate2(target, names[c].c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
         H5Dclose);
    if (!d.valid() || H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, g.g[c].data()) < 0)
      throw InputError(where + ": cannot write dataset '" + names[c] + "'");
    attributes(d.get());
  }
  out.commit();
}

}  // namespace conformesh::intrinsic
