// spatial_metric_registry.h — the spatial 3-metrics by name, as `--spatial-metric NAME --param k=v` and shape files
// name them: the analytic ones of spatial_metric.h and a grid read from HDF5 (sampled_spatial_metric.h).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "conformesh/intrinsic/metric/spatial_metric.h"

namespace conformesh::intrinsic {

// The names makeSpatialMetric knows, with their parameters and defaults, one per line, for `--help` and errors.
std::string spatialMetricList();
// Builds a spatial metric by name: "flat"; "schwarzschild-isotropic" (M = 1, cx = cy = cz = 0);
// "kerr-schild" (M = 1, a = 0, cx = cy = cz = 0); an HDF5 file FILE.h5[:/group]
// (or any name spelt *.h5 / *.hdf5): the sampled grid of sampled_spatial_metric.h, without parameters. Throws InputError naming an unknown name or parameter, or a
// parameter out of range (M ≤ 0, |a| > M).
std::unique_ptr<SpatialMetric> makeSpatialMetric(const std::string& name, const std::map<std::string, double>& params);

}  // namespace conformesh::intrinsic
