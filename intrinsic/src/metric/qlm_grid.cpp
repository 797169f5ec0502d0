// qlm_grid.cpp — QuasiLocalMeasures' 2-metric read into a SampledField (qlm_grid.h has the layout and conversion).
#include "conformesh/intrinsic/metric/qlm_grid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "hdf5_handles.h"

namespace conformesh::intrinsic {
namespace {

using hdf5_detail::Id;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

std::vector<std::string> rootNames(hid_t file) {
  std::vector<std::string> names;
  H5Literate(file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collectName, &names);
  return names;
}

// Datasets "QUASILOCALMEASURES::VAR[S] it=N tl=0 ..." by iteration N.
std::map<long, std::string> datasetsOf(const std::vector<std::string>& names, const std::string& var, int surface) {
  const std::string prefix = lower("QUASILOCALMEASURES::" + var + "[" + std::to_string(surface) + "] it=");
  std::map<long, std::string> found;
  for (const std::string& n : names) {
    const std::string l = lower(n);
    if (l.compare(0, prefix.size(), prefix) != 0) continue;
    if (l.find(" tl=0") == std::string::npos) continue;
    found[std::strtol(l.c_str() + prefix.size(), nullptr, 10)] = n;
  }
  return found;
}

struct Dataset {
  std::string name;
  std::vector<double> values;
  std::vector<hsize_t> dims;
};

Dataset readDataset(hid_t file, const std::string& name, const std::string& where) {
  Id set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw InputError(where + ": cannot open dataset '" + name + "'");
  Id space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  Dataset d{name, {}, std::vector<hsize_t>(std::max(rank, 0))};
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), d.dims.data(), nullptr);
  hsize_t count = 1;
  for (hsize_t n : d.dims) count *= n;
  d.values.resize(count);
  if (H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data()) < 0)
    throw InputError(where + ": dataset '" + name + "' is not a readable floating-point array");
  return d;
}

// The grid scalar VAR[S] at `iteration` (or the nearest stored one), when the file holds it.
std::optional<int> gridScalar(hid_t file, const std::vector<std::string>& names, const std::string& var,
                              int surface, long iteration, const std::string& where) {
  const auto sets = datasetsOf(names, var, surface);
  if (sets.empty()) return std::nullopt;
  auto it = sets.find(iteration);
  const std::string& name = it != sets.end() ? it->second : sets.rbegin()->second;
  const Dataset d = readDataset(file, name, where);
  if (d.values.size() != 1 || !std::isfinite(d.values[0]))
    throw InputError(where + ": dataset '" + name + "' must hold one finite number");
  return static_cast<int>(std::lround(d.values[0]));
}

struct Grid {
  int ntheta, nphi, ngt, ngp;
  double dtheta() const { return M_PI / (ntheta - 2 * ngt); }
  double dphi() const { return 2 * M_PI / (nphi - 2 * ngp); }
  double theta(int i) const { return (i - ngt + 0.5) * dtheta(); }
  double phi(int j) const { return (j - ngp) * dphi(); }
};

int gridValue(int given, std::optional<int> inFile, const char* name, const std::string& where) {
  if (inFile) {
    if (given != 0 && given != *inFile)
      throw InputError(where + ": the file's " + name + " is " + std::to_string(*inFile) + ", the option says " +
                       std::to_string(given));
    return *inFile;
  }
  if (given == 0 && std::string(name).find("nghosts") == std::string::npos)
    throw InputError(where + ": the file has no QUASILOCALMEASURES::" + name + " dataset; give " + name);
  return given;
}

Grid gridOf(hid_t file, const std::vector<std::string>& names, const QlmGridOptions& o, long it,
            const std::string& where) {
  const int s = o.surface;
  Grid g{gridValue(o.ntheta, gridScalar(file, names, "qlm_ntheta", s, it, where), "qlm_ntheta", where),
         gridValue(o.nphi, gridScalar(file, names, "qlm_nphi", s, it, where), "qlm_nphi", where),
         gridValue(o.nghoststheta, gridScalar(file, names, "qlm_nghoststheta", s, it, where), "qlm_nghoststheta",
                   where),
         gridValue(o.nghostsphi, gridScalar(file, names, "qlm_nghostsphi", s, it, where), "qlm_nghostsphi", where)};
  const int nv = g.ntheta - 2 * g.ngt, nu = g.nphi - 2 * g.ngp;
  if (g.ngt < 0 || g.ngp < 0 || nv < 2 || nu < 4 || nu % 2 != 0)
    throw InputError(where + ": grid ntheta " + std::to_string(g.ntheta) + ", nphi " + std::to_string(g.nphi) +
                     ", nghosts " + std::to_string(g.ngt) + " " + std::to_string(g.ngp) +
                     " leaves an interior of " + std::to_string(nv) + " x " + std::to_string(nu) +
                     " (theta x phi); need theta >= 2 and an even phi >= 4");
  return g;
}

std::string nodeText(const Grid& g, int i, int j) {
  std::ostringstream s;
  s.precision(6);
  s << "node (theta index " << i << ", phi index " << j << "; theta " << g.theta(i) << ", phi " << g.phi(j) << ")";
  return s.str();
}

void checkShape(const Dataset& d, const Grid& g, const std::string& where) {
  if (d.dims.size() != 2 || d.dims[1] < static_cast<hsize_t>(g.ntheta) || d.dims[0] < static_cast<hsize_t>(g.nphi)) {
    std::string shape;
    for (hsize_t n : d.dims) shape += (shape.empty() ? "" : " x ") + std::to_string(n);
    throw InputError(where + ": dataset '" + d.name + "' has shape (" + shape + "); expected at least (" +
                     std::to_string(g.nphi) + " x " + std::to_string(g.ntheta) +
                     ") = (nphi x ntheta), theta fastest");
  }
}

// Interior samples into the field, each checked finite and, per node, positive definite.
void convert(const Dataset* q[3], const Grid& g, SampledField& f, const std::string& where) {
  const size_t stride = q[0]->dims[1];
  f.nu = g.nphi - 2 * g.ngp, f.nv = g.ntheta - 2 * g.ngt;
  for (auto* c : {&f.guu, &f.guv, &f.gvv}) c->resize(static_cast<size_t>(f.nu) * f.nv);
  for (int jv = 0; jv < f.nv; ++jv)
    for (int iu = 0; iu < f.nu; ++iu) {
      const int i = jv + g.ngt, j = iu + g.ngp;  // file's θ and φ indices
      const size_t at = static_cast<size_t>(j) * stride + i;
      const double tt = q[0]->values[at], tp = q[1]->values[at], pp = q[2]->values[at];
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(q[c]->values[at]))
          throw InputError(where + ": dataset '" + q[c]->name + "': non-finite value at " + nodeText(g, i, j));
      if (!(tt > 0 && pp > 0 && tt * pp - tp * tp > 0))
        throw InputError(where + ": datasets '" + q[0]->name + "', '" + q[1]->name + "', '" + q[2]->name +
                         "': q is not positive definite at " + nodeText(g, i, j));
      const size_t k = static_cast<size_t>(jv) * f.nu + iu;
      f.guu[k] = pp, f.guv[k] = tp, f.gvv[k] = tt;
    }
}

}  // namespace

void QlmGridOptions::validate() const {
  if (surface < 0 || ntheta < 0 || nphi < 0 || nghoststheta < 0 || nghostsphi < 0)
    throw InputError("qlm grid: surface, ntheta, nphi and the ghost counts must be >= 0");
}

bool hasQlmTwoMetric(const std::string& path) {
  hdf5_detail::QuietErrors quiet;
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return false;
  for (const std::string& n : rootNames(file.get()))
    if (lower(n).rfind("quasilocalmeasures::qlm_qtt[", 0) == 0) return true;
  return false;
}

SampledField readQlmGridHdf5(const std::string& path, const QlmGridOptions& o) {
  o.validate();
  hdf5_detail::QuietErrors quiet;
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw InputError(path + ": cannot open as an HDF5 file");
  const std::vector<std::string> names = rootNames(file.get());
  const char* vars[3] = {"qlm_qtt", "qlm_qtp", "qlm_qpp"};
  std::map<long, std::string> sets[3];
  for (int c = 0; c < 3; ++c) {
    sets[c] = datasetsOf(names, vars[c], o.surface);
    if (sets[c].empty())
      throw InputError(path + ": missing dataset QUASILOCALMEASURES::" + vars[c] + "[" +
                       std::to_string(o.surface) + "] it=... tl=0 (component q_" + (vars[c] + 5) + ")");
  }
  const long it = o.iteration >= 0 ? o.iteration : sets[0].rbegin()->first;
  Dataset data[3];
  for (int c = 0; c < 3; ++c) {
    const auto found = sets[c].find(it);
    if (found == sets[c].end())
      throw InputError(path + ": missing dataset QUASILOCALMEASURES::" + vars[c] + "[" +
                       std::to_string(o.surface) + "] at it=" + std::to_string(it));
    data[c] = readDataset(file.get(), found->second, path);
  }
  const Grid g = gridOf(file.get(), names, o, it, path);
  for (const Dataset& d : data) checkShape(d, g, path);
  if (data[1].dims != data[0].dims || data[2].dims != data[0].dims)
    throw InputError(path + ": datasets '" + data[0].name + "', '" + data[1].name + "', '" + data[2].name +
                     "' differ in shape");
  SampledField f;
  f.source = path;
  f.domain.u0 = 0, f.domain.u1 = 2 * M_PI, f.domain.v0 = 0, f.domain.v1 = M_PI;
  f.domain.periodicU = true;
  const Dataset* q[3] = {&data[0], &data[1], &data[2]};
  convert(q, g, f, path);
  markPoleToPole(f, path);
  return f;
}

}  // namespace conformesh::intrinsic
