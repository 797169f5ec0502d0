// sampled_field_io.cpp — readSampledField: the signature test that chooses the HDF5 or the text reader.
#include "conformesh/intrinsic/metric/sampled_field_io.h"

#include <fstream>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/qlm_grid.h"

namespace conformesh::intrinsic {

SampledField readSampledField(const std::string& path) {
  // A file with the HDF5 signature (or FILE:/group naming one) is read as HDF5, whatever its extension.
  // Einstein Toolkit QuasiLocalMeasures output (datasets QUASILOCALMEASURES::qlm_qtt[0] ...) converts on the way in:
  // surface 0, its last iteration (qlm_grid.h).
  if (isHdf5File(path)) return hasQlmTwoMetric(path) ? readQlmGridHdf5(path) : readSampledFieldHdf5(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the metric field file");
  std::ostringstream s;
  s << in.rdbuf();
  return parseSampledField(s.str(), path);
}

}  // namespace conformesh::intrinsic
