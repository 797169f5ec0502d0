// End-to-end tests of `conformesh discretize`: --list, a family with parameters written to PLY and read back (chart
// coordinates u, v per vertex, edge lengths, the metric named in the comments), sampled fields (text and HDF5), and
// one-line errors naming the family, the parameter or the field file's line.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;

namespace {

using Run = conformesh::testing::CliRun;
using conformesh::testing::slurp;

fs::path dir() {
  return conformesh::testing::scratchDir();
}

Run runCli(const std::string& args) {
  return conformesh::testing::runConformesh(args);
}

}  // namespace

TEST_CASE("discretize --list describes every family and its parameters") {
  const Run r = runCli("discretize --list --json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.size() == metricFamilies().size());
  bool kerr = false;
  for (const auto& f : j)
    if (f["name"] == "kerr-newman") kerr = f["parameters"].size() == 3;
  CHECK(kerr);
}

TEST_CASE("discretize a family: PLY with lengths, u, v and the metric named") {
  const fs::path out = dir() / "kerr.ply";
  const Run r = runCli("-q discretize kerr-newman --param a=2 --param M=2 -r 6 -o " + out.string() + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["euler_characteristic"] == 2);
  CHECK(std::abs(j["gauss_bonnet_residual"].get<double>()) < 1e-10);
  // Extremal Kerr, M = 2: area 8πM r₊ = 8π·2·2.
  CHECK(j["smooth_area"].get<double>() == Approx(32 * M_PI).epsilon(1e-9));
  const MeshData d = readMesh(out.string());
  CHECK(d.nVertices == 362);
  CHECK(d.vertexProperties.at("u").size() == 362);
  CHECK(d.vertexProperties.at("v").size() == 362);
  CHECK(d.edges.size() == 1080);
  bool named = false;
  for (const std::string& c : d.comments) named = named || c.find("kerr-newman M=2 a=2 Q=0") != std::string::npos;
  CHECK(named);
}

TEST_CASE("discretize --field: a sampled metric file") {
  const fs::path field = dir() / "torus_field.txt";
  std::ofstream(field) << formatSampledField(sampleMetric(TorusMetric(3, 1), 24, 16));
  const fs::path out = dir() / "torus.ply";
  const Run r = runCli("-q discretize --field " + field.string() + " -r 6 -o " + out.string() + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["euler_characteristic"] == 0);
  CHECK(j["smooth_area"].get<double>() == Approx(12 * M_PI * M_PI).epsilon(1e-4));
}

TEST_CASE("discretize --field: an HDF5 field in a group, and a broken one named") {
  const fs::path field = dir() / "torus_field.h5";
  writeSampledFieldHdf5(sampleMetric(TorusMetric(3, 1), 24, 16), field.string(), "/surfaces/torus");
  const fs::path out = dir() / "torus_h5.ply";
  Run r = runCli("-q discretize --field " + field.string() + ":/surfaces/torus -r 6 -o " + out.string() + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["euler_characteristic"] == 0);
  CHECK(j["smooth_area"].get<double>() == Approx(12 * M_PI * M_PI).epsilon(1e-4));
  r = runCli("discretize --field " + field.string() + " -r 6 -o " + out.string());  // the root holds no field
  CHECK(r.status == 1);
  CHECK(r.err.find(field.string() + ": missing attribute 'chart'") != std::string::npos);
}

TEST_CASE("discretize errors: one line naming the family, parameter or file line") {
  Run r = runCli("discretize klein -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("unknown metric family 'klein'") != std::string::npos);
  r = runCli("discretize torus --param R=1 --param r=2 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("R must exceed") != std::string::npos);
  r = runCli("discretize sphere --param R=abc -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("'abc' is not a number") != std::string::npos);
  const fs::path bad = dir() / "bad_field.txt";
  std::ofstream(bad) << "conformesh-metric-field 1\nchart 0 1 0 1\ngrid 4 4\nperiodic_u no\nperiodic_v no\n"
                        "fields g_uu g_uv g_vv\ndata\n1 0 1\n1 5 1\n";
  r = runCli("discretize --field " + bad.string() + " -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("bad_field.txt:") != std::string::npos);
  CHECK(r.err.find("wrong grid shape") != std::string::npos);
  r = runCli("discretize sphere");
  CHECK(r.status == 1);
  CHECK(r.err.find("--output") != std::string::npos);
}
