// End-to-end tests of `conformesh remesh --field`: the Kerr horizon handed over as a pole-to-pole sampled field, in
// HDF5 (a group of the file) and in the text format, remeshed to PLY; the per-vertex smooth curvature is finite at the
// two pole vertices of T0 and equals the closed form there; both formats give the same mesh.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;
using conformesh::testing::runConformesh;

TEST_CASE("remesh --field: the Kerr horizon a = 0.95 as an HDF5 field, finite curvature at the poles") {
  const double a = 0.95;
  const KerrNewmanMetric kerr(1, a, 0);
  const SampledField field = sampleMetric(kerr, 128, 64);
  const fs::path dir = conformesh::testing::scratchDir(), h5 = dir / "kerr_field.h5", txt = dir / "kerr_field.txt";
  writeSampledFieldHdf5(field, h5.string(), "/horizons/AhA");
  std::ofstream(txt) << formatSampledField(field);

  const fs::path out = dir / "kerr_field_h5.ply", outText = dir / "kerr_field_txt.ply";
  const std::string common = " --eps 0.2 --no-check --json -o ";
  conformesh::testing::CliRun r =
      runConformesh("-q remesh --field " + h5.string() + ":/horizons/AhA" + common + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const MeshData d = readMesh(out.string());
  const std::vector<double>& K = d.vertexProperties.at("smooth_curvature");
  const std::vector<double>& v = d.vertexProperties.at("v");
  int poles = 0;
  for (size_t i = 0; i < K.size(); ++i) {
    REQUIRE(std::isfinite(K[i]));
    if (v[i] == 0 || v[i] == M_PI) {
      ++poles;
      // The analytic family's closed form at the pole against the field's spline limit (smooth_metric.cpp): the
      // 128 × 64 spline's K is second-order accurate, measured 3.3e-4 relative at both poles.
      CHECK(K[i] == Approx(kerr.gaussianCurvature(0, v[i])).epsilon(1e-3));
    }
  }
  CHECK(poles == 2);  // T0 of a sphere chart has a vertex at each pole

  r = runConformesh("-q remesh --field " + txt.string() + common + outText.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto jt = nlohmann::json::parse(r.out);
  // The two readers hand over the same samples bit for bit, so the pipeline is the same run, compared bit for bit
  // across two processes: this relies on the flow's two-thread loops splitting their work into fixed ranges that write
  // disjoint data (two_threads.h), so that the bits do not depend on the threads' timing.
  CHECK(jt["quality"]["vertices"] == j["quality"]["vertices"]);
  CHECK(jt["quality"]["min_angle_deg"] == j["quality"]["min_angle_deg"]);
  CHECK(jt["total_area"] == j["total_area"]);
  CHECK(readMesh(outText.string()).edges.size() == d.edges.size());
}

// `remesh --embed` on Kerr horizons (no known embedding): a/M = 0.5 has K > 0 everywhere (K < 0 at the poles only for
// a/M > √3/2), so an isometric fit exists and its positions are written; a/M = 0.99 has K < 0 at the axis, and an
// axisymmetric surface with K < 0 on its axis is not in R³: the fit cannot be isometric and the outputs keep the sphere.
namespace {
double edgeLengthError(const MeshData& d) {  // max relative |x_i − x_j| vs the written metric length
  double worst = 0;
  for (size_t e = 0; e < d.edges.size(); ++e) {
    const double l = (d.positions[d.edges[e].v0] - d.positions[d.edges[e].v1]).norm();
    worst = std::max(worst, std::abs(l - d.edges[e].length) / d.edges[e].length);
  }
  return worst;
}
}  // namespace

TEST_CASE("remesh --embed: Kerr a/M = 0.5 is embedded isometrically, a/M = 0.99 stays on the canonical sphere") {
  const fs::path dir = conformesh::testing::scratchDir();
  const fs::path out = dir / "kerr05_embed.ply";
  conformesh::testing::CliRun r =
      runConformesh("-q remesh kerr-newman --param a=0.5 --eps 0.3 --no-check --embed --json -o " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["embedding"]["isometric"] == true);
  CHECK(j["embedding"]["positions_written"] == true);
  const MeshData d = readMesh(out.string());
  REQUIRE(d.positions.size() == static_cast<size_t>(d.nVertices));
  // The criterion is max relative edge error ≤ τ = 1e-8 (EmbeddingOptions::tolerance): the file's positions meet it.
  CHECK(edgeLengthError(d) <= 1e-8);
  // Closed surface of the right size: Gauss–Bonnet of the EMBEDDED mesh (angles from positions) is 4π to round-off,
  // and its area is Smarr's 8πMr₊ short by the O(ε²) flat-triangle defect (measured −1e-3 here; bound 1 %).
  std::vector<double> angleSum(d.nVertices, 0.0);
  double area = 0;
  for (const auto& f : d.faces)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = d.positions[f[(k + 1) % 3]] - d.positions[f[k]],
                            b = d.positions[f[(k + 2) % 3]] - d.positions[f[k]];
      angleSum[f[k]] += std::atan2(a.cross(b).norm(), a.dot(b));
      if (k == 0) area += 0.5 * a.cross(b).norm();
    }
  double deficit = 0;
  for (double s : angleSum) deficit += 2 * M_PI - s;
  CHECK(deficit == Approx(4 * M_PI).margin(1e-9));
  const double rPlus = 1 + std::sqrt(1 - 0.25);
  CHECK(area == Approx(8 * M_PI * rPlus).epsilon(1e-2));

  const fs::path out99 = dir / "kerr99_embed.ply", vtk99 = dir / "kerr99_embed.vtk";
  r = runConformesh("-q remesh kerr-newman --param a=0.99 --eps 0.3 --no-check --embed --json -o " + out99.string() +
                    " --vtk " + vtk99.string());
  INFO(r.err);
  REQUIRE(r.status == 0);  // a fit that is not isometric is not an error of remesh
  j = nlohmann::json::parse(r.out);
  CHECK(j["embedding"]["isometric"] == false);
  CHECK(j["embedding"]["positions_written"] == false);
  CHECK(j["embedding"]["drawn_in"] == "canonical domain");
  CHECK(j["embedding"]["max_relative_residual"].get<double>() > 1e-8);
  CHECK(readMesh(out99.string()).positions.empty());
  std::ifstream vtk(vtk99);
  std::string title;
  std::getline(vtk, title);
  std::getline(vtk, title);  // legacy VTK: line 2 is the title
  CHECK(title.find("canonical domain") != std::string::npos);

  r = runConformesh("-q remesh kerr-newman --param a=0.99 --eps 0.3 --no-check --embed -o " + out99.string());
  CHECK(r.out.find("NOT isometric") != std::string::npos);
}
