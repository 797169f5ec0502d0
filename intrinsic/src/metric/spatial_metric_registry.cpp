// spatial_metric_registry.cpp — makeSpatialMetric and its list (spatial_metric_registry.h).
#include "conformesh/intrinsic/metric/spatial_metric_registry.h"

#include <set>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"

namespace conformesh::intrinsic {

std::string spatialMetricList() {
  return "flat                     (no parameters)\n"
         "schwarzschild-isotropic  M=1 cx=0 cy=0 cz=0\n"
         "kerr-schild              M=1 a=0 cx=0 cy=0 cz=0 (spin along +z, |a| <= M)\n"
         "FILE.h5[:/group]         gamma sampled on a Cartesian grid (gxx..gzz, origin, delta; no parameters)\n";
}

namespace {

// A name that is a file: an HDF5 file on disk (FILE or FILE:/group), or one spelled *.h5 / *.hdf5 (so that a missing
// file is reported as such, not as an unknown metric).
bool namesFile(const std::string& name) {
  const std::string file = name.substr(0, name.find(":/"));
  auto endsWith = [&](const std::string& e) {
    return file.size() > e.size() && file.compare(file.size() - e.size(), e.size(), e) == 0;
  };
  return endsWith(".h5") || endsWith(".hdf5") || isHdf5File(name);
}

}  // namespace

std::unique_ptr<SpatialMetric> makeSpatialMetric(const std::string& name, const std::map<std::string, double>& params) {
  if (namesFile(name)) {
    if (!params.empty())
      throw InputError("spatial metric " + name + ": a sampled metric takes no --param (found '" +
                       params.begin()->first + "')");
    return std::make_unique<SampledSpatialMetric>(readSpatialMetricHdf5(name));
  }
  std::set<std::string> known;
  if (name == "schwarzschild-isotropic") known = {"M", "cx", "cy", "cz"};
  else if (name == "kerr-schild") known = {"M", "a", "cx", "cy", "cz"};
  else if (name != "flat")
    throw InputError("unknown spatial metric '" + name + "'; known:\n" + spatialMetricList());
  for (const auto& [key, value] : params)
    if (!known.count(key))
      throw InputError("spatial metric '" + name + "': unknown parameter '" + key + "'; known:\n" +
                       spatialMetricList());
  auto get = [&](const char* key, double fallback) {
    const auto it = params.find(key);
    return it == params.end() ? fallback : it->second;
  };
  const Eigen::Vector3d c(get("cx", 0), get("cy", 0), get("cz", 0));
  if (name == "flat") return std::make_unique<FlatSpatialMetric>();
  if (name == "schwarzschild-isotropic") return std::make_unique<IsotropicSchwarzschildMetric>(get("M", 1), c);
  return std::make_unique<KerrSchildMetric>(get("M", 1), get("a", 0), c);
}

}  // namespace conformesh::intrinsic
