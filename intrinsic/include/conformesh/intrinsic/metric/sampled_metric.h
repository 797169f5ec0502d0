// sampled_metric.h — a metric handed over as samples, the way a physics code would: g_uu, g_uv, g_vv on a regular grid
// over a chart, with periodicity flags and optionally a pole-to-pole sphere chart; interpolated by tensor-product cubic
// B-splines (C², fourth-order accurate in g, second-order in its second derivatives and hence in K).
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
// included, NU ≥ 4). Every error (a malformed line, a wrong count, NaN, a sample that is not positive definite, a
// missing field) is an InputError naming FILE:LINE.
//
// Poles: near a coordinate pole g_uu → 0 like sin²v and g_uv like sin v, which no spline of g itself can keep positive.
// So pole-to-pole fields are interpolated in their regular form (g_uu/sin²v, g_uv/sin v, g_vv) on the doubled torus
// v ∈ [0,2π) (the great circle through both poles: the sample at (u, 2π − v) is the one at (u + π, v)), and g is
// rebuilt with the exact sin v factors — smooth through the pole and exactly degenerate at it.
#pragma once

#include <array>
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
// Reads a field file: the text format, or HDF5 (sampled_field_hdf5.h) when the file starts with HDF5's signature;
// `path:/group` names a field in a group of an HDF5 file.
SampledField readSampledField(const std::string& path);
// Checks shared by the readers: finite U0 < U1 and V0 < V1; and, for 'poles both', the sphere chart (periodic u,
// chart 0 2π 0 π to 1e-12), after which the field is marked pole-to-pole with the chart's ends set to 2π and π exactly.
// Both throw InputError prefixed by `where`.
void checkChartBounds(const ChartDomain& domain, const std::string& where);
void markPoleToPole(SampledField& field, const std::string& where);
// The text format (17 significant digits), e.g. to hand a sampled analytic metric to `conformesh discretize --field`.
std::string formatSampledField(const SampledField& field);
// Samples `metric` on the grid of the given shape (pole-to-pole when the metric's chart is a sphere chart).
SampledField sampleMetric(const SmoothMetric& metric, int nu, int nv);

class SampledMetric : public SmoothMetric {
 public:
  // Validates the field (shape, finiteness, positive-definiteness of every sample, naming the line or grid node) and
  // builds the splines.
  explicit SampledMetric(const SampledField& field);
  std::string family() const override { return "field"; }
  std::string description() const override;
  ChartDomain domain() const override { return field_.domain; }
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;  // analytic derivatives of the spline interpolant

 private:
  struct Spline2D {
    std::vector<double> c;  // coefficients, (nCu × nCv), u fastest
  };
  struct Axis {
    double x0 = 0, h = 1;  // node x_i = x0 + i h
    int n = 0, nc = 0;     // nodes, coefficients
    bool periodic = false;
  };
  // Value and first/second derivatives of one spline at (u, v): {f, fu, fv, fuu, fuv, fvv}.
  std::array<double, 6> evaluate(const Spline2D& s, double u, double v) const;

  SampledField field_;
  bool poles_ = false;
  Axis au_, av_;
  Spline2D suu_, suv_, svv_;
};

}  // namespace conformesh::intrinsic
