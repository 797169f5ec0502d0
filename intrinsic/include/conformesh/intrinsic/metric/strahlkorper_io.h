// strahlkorper_io.h — horizon shapes in the forms horizon finders write them, besides horizon_surface.h's coefficient
// JSON: the same coefficients in HDF5 (one group per shape), and the radius sampled on a θ–φ grid (JSON or HDF5),
// converted to coefficients by quadrature (Gauss–Legendre θ nodes) or least squares (uniform θ nodes) up to a stated
// l_max with the residual at the nodes reported. Layouts, node conventions and tolerances: docs/horizons.md §2,
// docs/formats.md ("Horizon shapes").
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/metric/horizon_surface.h"

namespace conformesh::intrinsic {

// θ nodes of a sampled radius, in increasing θ (north pole first); φ is always φ_k = 2πk/nφ, k = 0 … nφ−1.
//   GaussLegendre: θ_i = arccos x_i, x_i the nθ Gauss–Legendre roots in decreasing order (the SPHEREPACK-style
//                  collocation grid of spectral horizon finders);
//   Uniform:       θ_i = π (i + ½) / nθ (cell centres, no node on a pole).
enum class ThetaNodes { GaussLegendre, Uniform };
std::string toString(ThetaNodes n);                // "gauss-legendre", "uniform"
ThetaNodes parseThetaNodes(const std::string& s);  // InputError naming the value otherwise
std::vector<double> thetaNodes(ThetaNodes kind, int n);

// A radius sampled on a θ–φ grid: r(i, k) = r(θ_i, φ_k), nθ rows × nφ columns.
struct SampledRadius {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  ThetaNodes nodes = ThetaNodes::GaussLegendre;
  Eigen::MatrixXd r;
  int lMax = -1;  // the l_max to fit at (the file's `l_max`); −1: defaultSampledLMax
};

// The Strahlkörper of a sampled radius and how well it reproduces the samples.
struct RadiusFit {
  Strahlkorper shape{Eigen::Vector3d::Zero(), {{0, 0, 1.0}}};
  int lMax = 0;
  double maxResidual = 0, rmsResidual = 0;  // max and RMS of |r_fit(θ_i, φ_k) − r(i, k)| over the nodes
  ThetaNodes nodes = ThetaNodes::GaussLegendre;
  int nTheta = 0, nPhi = 0;  // the grid fitted
};

// The default l_max of a grid: min(nθ − 1, (nφ − 1)/2), the largest for which the Gauss–Legendre projection is exact
// for a radius band-limited to l_max (and the least-squares problem of a uniform grid overdetermined).
int defaultSampledLMax(int nTheta, int nPhi);
// Gauss–Legendre: a_lm = Σ_ik w_i (2π/nφ) r_ik Y_lm(θ_i, φ_k) (exact for r band-limited to L when l_max + L ≤ 2nθ − 1
// and l_max + L < nφ). Uniform: the least-squares a_lm (Householder QR). lMax < 0 takes s.lMax, then the default.
// An lMax above the default, a grid smaller than 2 × 3, r non-finite or ≤ 0 at a node (named by i, k, θ, φ), or a
// fitted radius not positive on the check grid is an InputError naming `source`.
RadiusFit fitSampledRadius(const SampledRadius& s, int lMax, const std::string& source);
// The radius of a shape on a grid (for tests and `generate horizon-series --sampled`).
SampledRadius sampleStrahlkorper(const Strahlkorper& s, ThetaNodes nodes, int nTheta, int nPhi);

// One shape in an HDF5 file or a JSON file, with what a time series needs (horizon_surface.h's HorizonFileMetadata).
struct HorizonShapeRecord {
  Strahlkorper shape{Eigen::Vector3d::Zero(), {{0, 0, 1.0}}};
  HorizonFileMetadata meta;
  bool sampled = false;  // given as a sampled radius, fitted
  RadiusFit fit;         // when sampled
};

// A shape path is HDF5 when it names FILE.h5 / FILE.hdf5 (optionally FILE.h5:/group) or a file with HDF5's
// signature; else it is JSON.
bool isHdf5ShapePath(const std::string& pathAndGroup);

// An HDF5 group holding a shape (docs/formats.md): `center` (attribute or dataset of 3 numbers), and either the
// dataset `coefficients` (n × 3 rows l, m, a_lm; l and m integral) with optional string attribute `convention`, or
// the dataset `radius` (nθ × nφ) with optional string attribute `theta_nodes` ("gauss-legendre", default, or
// "uniform") and integer attribute `l_max`; optional attributes `time` (number), `spatial_metric` (string) and
// `param_<name>` (numbers, the spatial metric's parameters). Throws InputError naming FILE:/group, the dataset or
// attribute, and the element (row, or node i, k) with expected vs found; the radius must be positive (check grid).
HorizonShapeRecord readHorizonShapeHdf5(const std::string& pathAndGroup);
// The JSON shape file of horizon_surface.h, or a sampled radius in JSON: {"center": [x, y, z], "radius": [[r_00, …,
// r_0(nφ−1)], …] (nθ rows), optional "theta_nodes", "l_max"}; plus the metadata keys of readHorizonMetadata.
HorizonShapeRecord readHorizonShapeJson(const std::string& path);
// Either, by isHdf5ShapePath. Every `--horizon SHAPE` and horizon sweep case reads through this.
HorizonShapeRecord readHorizonShape(const std::string& pathAndGroup);

// The groups of an HDF5 file that hold a shape, or are meant to (a link `coefficients`, `radius` or `center`, or an
// attribute `center` or `time`), as "/name", in name order (recursively, the root as "/"); a group so marked but
// malformed is listed, so that a series reports it in its row. Throws InputError when the file does not open as HDF5.
std::vector<std::string> listHorizonShapeGroups(const std::string& path);
// Whether FILE.h5:/group is such a group (false, never throwing, when the file or group does not open).
bool hdf5GroupHoldsShape(const std::string& pathAndGroup);

// Writes shapes into one new HDF5 file, one group each (to a temporary name, renamed; InputError on failure). A record
// with `sampled` set is written as its `fit`'s sampled radius `samples`; else as coefficients (orthonormal).
struct HorizonShapeGroup {
  std::string group;  // "/t000" …
  HorizonShapeRecord record;
  SampledRadius samples;  // used when record.sampled
};
void writeHorizonShapesHdf5(const std::string& path, const std::vector<HorizonShapeGroup>& groups);

}  // namespace conformesh::intrinsic
