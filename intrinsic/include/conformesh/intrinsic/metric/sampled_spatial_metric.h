// sampled_spatial_metric.h — a spatial 3-metric γ_ij sampled on a regular Cartesian grid, as numerical-relativity
// codes write it (Einstein Toolkit ADMBase gxx … gzz through CarpetIOHDF5; SpECTRE's SpatialMetric_xx … names), and
// its interpolant: a SpatialMetric (spatial_metric.h) that a horizon surface (horizon_surface.h) can be put in.
//
// Interpolation (docs/horizons.md §1b): per axis the C¹ piecewise-cubic Hermite interpolant whose node derivatives are
// the fourth-order centred differences (f_{i−2} − 8f_{i−1} + 8f_{i+1} − f_{i+2})/12h; in 3-D its tensor product
// (a 6×6×6 stencil). Error O(h⁴) in γ_ij and O(h³) in ∂_k γ_ij for smooth data; local, so junk inside an excised
// or punctured region reaches no further than 3 nodes. Points closer than 2 cells to the grid's faces cannot be
// interpolated (InputError naming the point and the usable box).
//
// HDF5 layout (readSpatialMetricHdf5; FILE.h5 or FILE.h5:/group):
//   six datasets in the group, each 3-D of shape (nz, ny, nx) (C order: x fastest, the order Cactus and Carpet
//   write), float of any IEEE width, named by one of
//     "gxx gxy gxz gyy gyz gzz"                                (ADMBase names)
//     "ADMBASE::gxx it=…"  …                                   (CarpetIOHDF5's dataset names: one dataset each)
//     "SpatialMetric_xx SpatialMetric_xy … SpatialMetric_zz"   (SpECTRE's tensor-component names)
//   attributes "origin" and "delta" (float64[3], x y z: the position of sample [0][0][0] and the spacing) on every
//   dataset (Carpet writes them there) or on the group; all six must agree. Ghost zones are ordinary samples (the
//   origin is that of the first stored point, as Carpet writes it). Every error is an InputError naming the file,
//   group and dataset and, for a sample, its index [k][j][i] and position.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/metric/spatial_metric.h"

namespace conformesh::intrinsic {

// The samples: component c ∈ {xx, xy, xz, yy, yz, zz} (index 0..5) at node (i, j, k), position origin + (i, j, k)·delta,
// stored at g[c][i + nx (j + ny k)].
struct SpatialMetricGrid {
  std::string source;  // file and group, for messages
  std::array<int, 3> n{0, 0, 0};
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), delta = Eigen::Vector3d::Ones();
  std::array<std::vector<double>, 6> g;
  std::array<std::string, 6> datasets;  // the components' dataset names, for messages (empty: gxx … gzz)
  long long index(int i, int j, int k) const { return i + static_cast<long long>(n[0]) * (j + n[1] * k); }
  Eigen::Vector3d position(int i, int j, int k) const;
};

// The component names of a naming scheme, and the names themselves: "admbase" (gxx …), "spectre" (SpatialMetric_xx …).
const std::array<std::string, 6>& spatialMetricComponentNames(const std::string& naming);

// Throws InputError naming `grid.source`, the component and the node when: an axis has fewer than 6 nodes, a spacing
// is not finite and > 0, the origin is not finite, a sample count differs from nx·ny·nz, a sample is not finite, or
// γ at a node is not positive definite (leading minors γ_xx, γ_xx γ_yy − γ_xy², det γ; the first one ≤ 0 is named).
void checkSpatialMetricGrid(const SpatialMetricGrid& grid);

// γ of `metric` at the nodes of the grid (n, origin, delta); `source` becomes the grid's.
SpatialMetricGrid sampleSpatialMetric(const SpatialMetric& metric, const std::array<int, 3>& n,
                                      const Eigen::Vector3d& origin, const Eigen::Vector3d& delta,
                                      const std::string& source = "sampled");

class SampledSpatialMetric : public SpatialMetric {
 public:
  explicit SampledSpatialMetric(SpatialMetricGrid grid);  // checkSpatialMetricGrid first
  std::string name() const override { return "sampled"; }
  std::string description() const override;  // source, nodes, spacing
  Eigen::Matrix3d gamma(const Eigen::Vector3d& x) const override;
  SpatialMetricJet jet(const Eigen::Vector3d& x) const override;
  const SpatialMetricGrid& grid() const { return grid_; }
  // The box where the 6-node stencil fits: origin + 2·delta to origin + (n − 3)·delta.
  Eigen::Vector3d lower() const;
  Eigen::Vector3d upper() const;

 private:
  SpatialMetricJet evaluate(const Eigen::Vector3d& x, bool derivatives) const;
  SpatialMetricGrid grid_;
  std::vector<std::array<double, 6>> packed_;  // the six components of each node together (one cache line)
};

// Reads the layout above from `pathAndGroup` ("FILE.h5" or "FILE.h5:/group").
SpatialMetricGrid readSpatialMetricHdf5(const std::string& pathAndGroup);
// Writes it (float64, attributes on the group and on every dataset), creating or truncating `path`; `group` ("/" =
// root) is created with its parents; `naming` is "admbase" or "spectre".
void writeSpatialMetricHdf5(const SpatialMetricGrid& grid, const std::string& path, const std::string& group = "/",
                            const std::string& naming = "admbase");

}  // namespace conformesh::intrinsic
