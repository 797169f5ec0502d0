// sampled_field.h — a metric handed over as samples, the way a physics code would: g_uu, g_uv, g_vv on a regular grid
// over a chart, with periodicity flags and optionally a pole-to-pole sphere chart; and its text format. No HDF5 here:
// sampled_field_hdf5.h reads that container, sampled_field_io.h picks the reader for a file, and sampled_metric.h
// interpolates a field into a SmoothMetric.
//
// Text format (docs/metrics.md has a full example):
//   conformesh-metric-field 1
//   chart U0 U1 V0 V1
//   grid NU NV
//   periodic_u yes|no
//   periodic_v yes|no
//   poles none|both        (both: u ∈ [0,2π) periodic, v ∈ [0,π], v-nodes cell-centred (j+½)π/NV, NU even)
//   fields g_uu g_uv g_vv   (column order of the data lines; all three required)
//   data
//   NU·NV lines, u varying fastest, one number per field
// '#' starts a comment. Node positions: periodic axes U0 + i(U1−U0)/NU; other axes U0 + i(U1−U0)/(NU−1) (endpoints
// included, NU ≥ 4). Every error (a malformed line, a wrong count, NaN, a missing field) is an InputError naming
// FILE:LINE.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

struct SampledField {
  std::string source;  // file name, for messages and descriptions
  ChartDomain domain;  // periodicity and poles as in the file
  int nu = 0, nv = 0;
  std::vector<double> guu, guv, gvv;  // nu·nv samples, u fastest
  std::vector<int> lines;             // source line of each sample (empty for fields built in memory)

  // Chart coordinates of grid node (i, j), following the conventions above.
  double nodeU(int i) const;
  double nodeV(int j) const;
};

// Parses the text format; throws InputError "SOURCE:LINE: ..." on any problem.
SampledField parseSampledField(const std::string& text, const std::string& source);
// Checks shared by the readers: finite U0 < U1 and V0 < V1; and, for 'poles both', the sphere chart (periodic u,
// chart 0 2π 0 π to 1e-12), after which the field is marked pole-to-pole with the chart's ends set to 2π and π exactly.
// Both throw InputError prefixed by `where`.
void checkChartBounds(const ChartDomain& domain, const std::string& where);
void markPoleToPole(SampledField& field, const std::string& where);
// The text format (17 significant digits), e.g. to hand a sampled analytic metric to `conformesh discretize --field`.
std::string formatSampledField(const SampledField& field);
// Samples `metric` on the grid of the given shape (pole-to-pole when the metric's chart is a sphere chart).
SampledField sampleMetric(const SmoothMetric& metric, int nu, int nv);

}  // namespace conformesh::intrinsic
