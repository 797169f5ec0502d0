// End-to-end tests of `conformesh repair`, `--repair` and `conformesh field check`: CGAL's polygon_mesh.off (three
// pinched vertices) is refused by `info` with the hint, repaired by `repair` (its JSON counts, and the written file
// read back as a manifold whose χ is the input's V − E + F plus the three extra fans, 16344 − 48612 + 32245 + 3 = −20)
// and by `info --repair`; `field check` on the Kerr horizon (a/M = 0.95) prints area 8πMr₊ and ∫K dA = 4π, and refuses
// the field without its `poles both` line with exit status 1 and one line.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/sampled_field.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;
using conformesh::testing::runConformesh;
using Catch::Contains;

TEST_CASE("conformesh repair and --repair on CGAL's polygon_mesh.off") {
  const std::string in = std::string(CONFORMESH_TEST_DATA_DIR) + "/polygon_mesh.off";
  const auto refused = runConformesh("-q info " + in);
  CHECK(refused.status == 1);
  CHECK_THAT(refused.err, Contains("conformesh: error: ") && Contains("pinched vertex 4113") &&
                              Contains("`--repair` would fix it"));
  const fs::path out = conformesh::testing::scratchDir() / "fixed.ply";
  const auto r = runConformesh("-q repair " + in + " -o " + out.string() + " --json");
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["vertex_fans_split"]["count"] == 3);
  CHECK(j["non_manifold_edges"]["count"] == 0);
  CHECK(j["result"]["euler_characteristic"] == -20);
  ConversionReport conv;
  const MeshSummary s = summarize(toTriangulation(readMesh(out.string()), &conv));
  CHECK(conv.build.reorientedFaces == 0);
  CHECK(s.eulerCharacteristic == -20);
  CHECK(s.faces == 32245);
  const auto info = runConformesh("info --repair " + in + " --json");
  REQUIRE(info.status == 0);
  CHECK(nlohmann::json::parse(info.out)["euler_characteristic"] == -20);
  CHECK_THAT(info.err, Contains("repair of ") && Contains("vertex fans given their own vertex: 3"));
}

TEST_CASE("conformesh field check: the Kerr horizon, and the field without `poles both`") {
  SampledField f = sampleMetric(KerrNewmanMetric(1.0, 0.95, 0.0), 64, 32);
  const fs::path good = conformesh::testing::scratchDir() / "kerr.txt";
  std::ofstream(good) << formatSampledField(f);
  const auto r = runConformesh("-q field check " + good.string() + " --json");
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double rp = 1 + std::sqrt(1 - 0.95 * 0.95);
  CHECK(j["shape"] == "sphere");
  CHECK(j["euler_characteristic"] == 2);
  CHECK(j["area"].get<double>() == Approx(8 * M_PI * rp).epsilon(1e-6));  // fourth order in h = π/32
  CHECK(j["total_curvature"].get<double>() == Approx(4 * M_PI).epsilon(1e-6));  // see test_sampled_metric
  f.domain.poleAtV0 = f.domain.poleAtV1 = false;
  const fs::path bad = conformesh::testing::scratchDir() / "nopoles.txt";
  std::ofstream(bad) << formatSampledField(f);
  const auto e = runConformesh("-q field check " + bad.string());
  CHECK(e.status == 1);
  CHECK_THAT(e.err, Contains("conformesh: error: ") && Contains("is this a sphere? add `poles both`"));
}
