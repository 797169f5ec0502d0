// sampled_spatial_metric.cpp — the grid checks and the tensor-product C¹ cubic Hermite interpolant of
// sampled_spatial_metric.h (docs/horizons.md §1b).
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "metric/family_checks.h"

namespace conformesh::intrinsic {

namespace {

using metric_detail::fmt;

constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};  // (i, j) -> component

std::string pointText(const Eigen::Vector3d& x) {
  return "(" + fmt(x.x()) + ", " + fmt(x.y()) + ", " + fmt(x.z()) + ")";
}

std::string componentName(const SpatialMetricGrid& g, int c) {
  const std::string& d = g.datasets[c];
  return "dataset '" + (d.empty() ? spatialMetricComponentNames("admbase")[c] : d) + "'";
}

std::string nodeText(const SpatialMetricGrid& g, int i, int j, int k) {
  return "[" + std::to_string(k) + "][" + std::to_string(j) + "][" + std::to_string(i) + "] (node i=" +
         std::to_string(i) + " j=" + std::to_string(j) + " k=" + std::to_string(k) + ", x = " +
         pointText(g.position(i, j, k)) + ")";
}

// The 1-D weights of the six samples f_{i−2} … f_{i+3} in the cell [i, i+1] at s ∈ [0, 1], and of their s-derivative:
// the cubic Hermite p(s) = h00 f_i + h10 d_i + h01 f_{i+1} + h11 d_{i+1} with d_i = (f_{i−2} − 8f_{i−1} + 8f_{i+1} −
// f_{i+2})/12 (grid units).
void hermiteWeights(double s, double w[6], double dw[6]) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  // d_i uses offsets −2, −1, +1, +2 about i (stencil slots 0, 1, 3, 4); d_{i+1} about i+1 (slots 1, 2, 4, 5).
  const double c[4] = {1.0 / 12, -8.0 / 12, 8.0 / 12, -1.0 / 12};
  auto fill = [&](double a00, double a10, double a01, double a11, double out[6]) {
    for (int q = 0; q < 6; ++q) out[q] = 0;
    out[2] += a00, out[3] += a01;
    const int di[4] = {0, 1, 3, 4}, dj[4] = {1, 2, 4, 5};
    for (int q = 0; q < 4; ++q) out[di[q]] += a10 * c[q], out[dj[q]] += a11 * c[q];
  };
  fill(h00, h10, h01, h11, w);
  fill(d00, d10, d01, d11, dw);
}

}  // namespace

Eigen::Vector3d SpatialMetricGrid::position(int i, int j, int k) const {
  return origin + Eigen::Vector3d(i * delta.x(), j * delta.y(), k * delta.z());
}

const std::array<std::string, 6>& spatialMetricComponentNames(const std::string& naming) {
  static const std::array<std::string, 6> adm{"gxx", "gxy", "gxz", "gyy", "gyz", "gzz"};
  static const std::array<std::string, 6> spectre{"SpatialMetric_xx", "SpatialMetric_xy", "SpatialMetric_xz",
                                                  "SpatialMetric_yy", "SpatialMetric_yz", "SpatialMetric_zz"};
  if (naming == "admbase") return adm;
  if (naming == "spectre") return spectre;
  throw InputError("spatial metric grid: unknown component naming '" + naming + "' (known: admbase, spectre)");
}

void checkSpatialMetricGrid(const SpatialMetricGrid& g) {
  const std::string& w = g.source;
  for (int a = 0; a < 3; ++a) {
    if (g.n[a] < 6)
      throw InputError(w + ": axis " + "xyz"[a] + " has " + std::to_string(g.n[a]) +
                       " nodes; the 6-node interpolation stencil needs at least 6");
    if (!(std::isfinite(g.delta[a]) && g.delta[a] > 0))
      throw InputError(w + ": attribute 'delta' must be finite and > 0, found " + fmt(g.delta[a]) + " on axis " +
                       "xyz"[a]);
  }
  if (!g.origin.allFinite()) throw InputError(w + ": attribute 'origin' must be finite");
  const size_t count = static_cast<size_t>(g.n[0]) * g.n[1] * g.n[2];
  for (int c = 0; c < 6; ++c)
    if (g.g[c].size() != count)
      throw InputError(w + ": " + componentName(g, c) + " has " + std::to_string(g.g[c].size()) +
                       " samples, expected nx*ny*nz = " + std::to_string(count));
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const long long n = g.index(i, j, k);
        double v[6];
        for (int c = 0; c < 6; ++c) {
          v[c] = g.g[c][n];
          if (!std::isfinite(v[c]))
            throw InputError(w + ": " + componentName(g, c) + " " + nodeText(g, i, j, k) + " is " +
                             formatNumber(v[c]) + "; every sample must be finite");
        }
        const double m2 = v[0] * v[3] - v[1] * v[1];
        const double det = v[0] * (v[3] * v[5] - v[4] * v[4]) - v[1] * (v[1] * v[5] - v[4] * v[2]) +
                           v[2] * (v[1] * v[4] - v[3] * v[2]);
        const char* bad = !(v[0] > 0) ? "gxx" : !(m2 > 0) ? "gxx*gyy - gxy^2" : !(det > 0) ? "det gamma" : nullptr;
        if (bad)
          throw InputError(w + ": gamma (" + componentName(g, 0) + " ... " + componentName(g, 5) + ") at " +
                           nodeText(g, i, j, k) + " is not positive definite (" + bad +
                           " <= 0; gxx gxy gxz gyy gyz gzz = " + fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]) + " " +
                           fmt(v[3]) + " " + fmt(v[4]) + " " + fmt(v[5]) + ")");
      }
}

SpatialMetricGrid sampleSpatialMetric(const SpatialMetric& metric, const std::array<int, 3>& n,
                                      const Eigen::Vector3d& origin, const Eigen::Vector3d& delta,
                                      const std::string& source) {
  SpatialMetricGrid g;
  g.source = source, g.n = n, g.origin = origin, g.delta = delta;
  const size_t count = static_cast<size_t>(n[0]) * n[1] * n[2];
  for (auto& c : g.g) c.resize(count);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Eigen::Matrix3d m = metric.gamma(g.position(i, j, k));
        const long long idx = g.index(i, j, k);
        for (int a = 0; a < 3; ++a)
          for (int b = a; b < 3; ++b) g.g[kPair[a][b]][idx] = m(a, b);
      }
  return g;
}

SampledSpatialMetric::SampledSpatialMetric(SpatialMetricGrid grid) : grid_(std::move(grid)) {
  checkSpatialMetricGrid(grid_);
  packed_.resize(grid_.g[0].size());
  for (size_t n = 0; n < packed_.size(); ++n)
    for (int c = 0; c < 6; ++c) packed_[n][c] = grid_.g[c][n];
}

std::string SampledSpatialMetric::description() const {
  return "sampled " + grid_.source + " (" + std::to_string(grid_.n[0]) + "x" + std::to_string(grid_.n[1]) + "x" +
         std::to_string(grid_.n[2]) + " nodes, spacing " + fmt(grid_.delta.x()) + "," + fmt(grid_.delta.y()) + "," +
         fmt(grid_.delta.z()) + ", cubic Hermite O(h^4))";
}

Eigen::Vector3d SampledSpatialMetric::lower() const {
  return grid_.origin + 2 * grid_.delta;
}
Eigen::Vector3d SampledSpatialMetric::upper() const {
  return grid_.position(grid_.n[0] - 3, grid_.n[1] - 3, grid_.n[2] - 3);
}

Eigen::Matrix3d SampledSpatialMetric::gamma(const Eigen::Vector3d& x) const {
  return evaluate(x, false).g;
}
SpatialMetricJet SampledSpatialMetric::jet(const Eigen::Vector3d& x) const {
  return evaluate(x, true);
}

// Per axis: the cell i with i − 2 ≥ 0 and i + 3 ≤ n − 1 holding x, the weights of its six samples; then the triple
// sum over the 6×6×6 stencil for each component, with one derivative weight per derivative.
SpatialMetricJet SampledSpatialMetric::evaluate(const Eigen::Vector3d& x, bool derivatives) const {
  int base[3];
  double w[3][6], dw[3][6];
  for (int a = 0; a < 3; ++a) {
    const double t = (x[a] - grid_.origin[a]) / grid_.delta[a];
    const int n = grid_.n[a];
    if (!(t >= 2 - 1e-9 && t <= n - 3 + 1e-9))
      throw InputError("spatial metric " + description() + ": point " + pointText(x) +
                       " outside the interpolation box " + pointText(lower()) + " to " + pointText(upper()) +
                       " (2 nodes from each face)");
    const int i = std::min(std::max(static_cast<int>(std::floor(t)), 2), n - 4);
    hermiteWeights(t - i, w[a], dw[a]);
    base[a] = i - 2;
  }
  double val[6] = {0}, der[3][6] = {{0}};
  for (int r = 0; r < 6; ++r)
    for (int q = 0; q < 6; ++q) {
      const double wyz = w[1][q] * w[2][r], dyz = dw[1][q] * w[2][r], ydz = w[1][q] * dw[2][r];
      for (int p = 0; p < 6; ++p) {
        const std::array<double, 6>& node = packed_[grid_.index(base[0] + p, base[1] + q, base[2] + r)];
        for (int c = 0; c < 6; ++c) {
          const double f = node[c];
          val[c] += w[0][p] * wyz * f;
          if (derivatives) {
            der[0][c] += dw[0][p] * wyz * f;
            der[1][c] += w[0][p] * dyz * f;
            der[2][c] += w[0][p] * ydz * f;
          }
        }
      }
    }
  SpatialMetricJet j;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      j.g(a, b) = val[kPair[a][b]];
      for (int k = 0; k < 3; ++k) j.d[k](a, b) = der[k][kPair[a][b]] / grid_.delta[k];
    }
  return j;
}

}  // namespace conformesh::intrinsic
