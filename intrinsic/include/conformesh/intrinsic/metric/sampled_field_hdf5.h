// sampled_field_hdf5.h — sampled metric fields (sampled_field.h) in HDF5, the container physics codes write: three
// 2-D datasets g_uu, g_uv, g_vv of shape (NV, NU) and the chart's description as attributes of their group.
//
// Layout (docs/metrics.md §4 has an h5py example):
//   group (the file's root, or FILE.h5:/path/to/group)
//     attribute  chart       float64[4]   U0 U1 V0 V1
//     attribute  periodic_u  integer      0 or 1
//     attribute  periodic_v  integer      0 or 1
//     attribute  poles       string       "none" or "both"            (optional, default "none")
//     attribute  conformesh_metric_field  integer 1                   (optional format version)
//     dataset    g_uu, g_uv, g_vv         float (any IEEE width), shape (NV, NU): row j = v-node j, u fastest
// The grid conventions are the text format's (node positions, poles). Every error is an InputError naming the file,
// the group and the dataset or attribute; HDF5's own error stack is not printed.
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/sampled_field.h"

namespace conformesh::intrinsic {

// Whether the file at `path`, or at FILE of `FILE:/group` (when FILE exists and the whole string does not), starts
// with the HDF5 signature \x89HDF\r\n\x1a\n.
bool isHdf5File(const std::string& pathAndGroup);

// Reads `path`, or `path:/group` for a field stored in a group other than the root. The samples are checked by
// SampledMetric's constructor as for the text format; this reader checks the layout, the shapes, the attributes and
// that every sample is finite (naming dataset and index).
SampledField readSampledFieldHdf5(const std::string& pathAndGroup);

// Writes `field` in the layout above (float64 datasets), creating or truncating `path`; `group` ("/" = root) is
// created with its parents.
void writeSampledFieldHdf5(const SampledField& field, const std::string& path, const std::string& group = "/");

}  // namespace conformesh::intrinsic
