// End-to-end tests of `conformesh remesh --field`: the Kerr horizon handed over as a pole-to-pole sampled field, in
// HDF5 (a group of the file) and in the text format, remeshed to PLY; the per-vertex smooth curvature is finite at the
// two pole vertices of T0 and equals the closed form there; both formats give the same mesh.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

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
