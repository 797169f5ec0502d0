// sampled_field_io.h — reading a sampled metric field from a file, whichever container it is in: the one dispatch
// between the text format (sampled_field.h) and HDF5 (sampled_field_hdf5.h). Depends on both readers; they do not
// depend on it.
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/sampled_field.h"

namespace conformesh::intrinsic {

// Reads a field file: HDF5 when the file starts with HDF5's signature (whatever its extension) — Einstein Toolkit
// QuasiLocalMeasures output (qlm_grid.h, surface 0, last iteration) when it holds QUASILOCALMEASURES::qlm_qtt[...] —,
// else the text format.
// `path:/group` names a field in a group of an HDF5 file. Throws InputError naming the file (and line, dataset or
// attribute) for a file that cannot be opened or read; the samples are checked by SampledMetric's constructor.
SampledField readSampledField(const std::string& path);

}  // namespace conformesh::intrinsic
