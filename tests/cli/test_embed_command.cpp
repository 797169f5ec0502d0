// End-to-end tests of `conformesh embed`: an ellipsoid's metric mesh fits isometrically (exit 0, JSON report, output
// PLY whose straight edges have the input's lengths), the Kerr horizon at a/M = 0.99 does not (exit 1 naming the
// residual, the best fit still written), --init, and one-line errors for bad input.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;

namespace {

using Run = conformesh::testing::CliRun;

fs::path dir() {
  return conformesh::testing::scratchDir();
}

Run runCli(const std::string& args) {
  return conformesh::testing::runConformesh(args);
}

// T0 of a metric family (lengths = geodesic lengths), written as PLY (metric-only unless withPositions); returns its
// path.
std::string metricMesh(const std::string& family, const std::map<std::string, double>& params, int resolution,
                       const std::string& name, bool withPositions = false) {
  const auto m = makeMetric(family, params);
  DiscretizationOptions o;
  o.resolution = resolution;
  MeshData data = discretizeMetric(*m, o);
  // discretizeMetric attaches the family's embedding when it has one; a metric-only file has none.
  if (!withPositions) data.positions.clear();
  REQUIRE(data.positions.size() == (withPositions ? static_cast<std::size_t>(data.nVertices) : 0u));
  const std::string path = (dir() / name).string();
  writeMesh(data, path);
  return path;
}

}  // namespace

TEST_CASE("embed: an ellipsoid's metric mesh fits isometrically, and the output's edges have the input's lengths") {
  const std::string in = metricMesh("ellipsoid", {{"f", 0.3}}, 5, "ellipsoid.ply");
  const std::string out = (dir() / "ellipsoid_fit.ply").string();
  const Run r = runCli("embed " + in + " -o " + out + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["isometric"] == true);
  CHECK(j["max_relative_residual"].get<double>() < 1e-12);
  CHECK(j["vertices"] == 252);
  CHECK(j["verdict"].get<std::string>().rfind("isometric to tolerance", 0) == 0);
  // One progress line per LM iteration on stderr.
  CHECK(r.err.find("embed: fit iteration 1:") != std::string::npos);

  const MeshData fit = readMesh(out);
  REQUIRE(fit.positions.size() == 252);
  REQUIRE(fit.edgeProperties.count("relative_residual") == 1);
  const MeshData input = readMesh(in);
  REQUIRE(fit.edges.size() == input.edges.size());
  double worst = 0;
  for (const auto& e : fit.edges)
    worst = std::max(worst, std::abs((fit.positions[e.v0] - fit.positions[e.v1]).norm() / e.length - 1));
  CHECK(worst < 1e-12);
  CHECK(fit.vertexProperties.count("u") == 1);  // the input's vertex properties are carried along
}

TEST_CASE("embed: the Kerr horizon at a/M = 0.99 is not isometric — exit 1 naming the residual, best fit written") {
  const std::string in = metricMesh("kerr-newman", {{"a", 0.99}}, 4, "kerr.ply");
  const std::string out = (dir() / "kerr_fit.ply").string();
  fs::remove(out);
  const Run r = runCli("embed " + in + " -o " + out + " --max-iterations 60");
  CHECK(r.status == 1);
  CHECK(r.err.find("not isometric: residual") != std::string::npos);
  CHECK(r.err.find("best fit was written to " + out) != std::string::npos);
  CHECK(r.out.find("verdict") != std::string::npos);  // the text report is printed before the failure
  const MeshData fit = readMesh(out);
  CHECK(fit.positions.size() == static_cast<std::size_t>(fit.nVertices));
}

TEST_CASE("embed --init starts from given positions") {
  const std::string in = metricMesh("ellipsoid", {{"f", 0.2}}, 4, "ellipsoid_init.ply", true);
  const Run r = runCli("embed " + in + " --init " + in + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["start"] == "initial positions");
  CHECK(j["isometric"] == true);
}

TEST_CASE("embed: bad input gets a one-line error naming it") {
  const std::string in = metricMesh("ellipsoid", {}, 4, "ellipsoid_bad.ply");
  const std::string small = metricMesh("ellipsoid", {}, 2, "ellipsoid_small.ply", true);
  Run r = runCli("embed " + in + " --init " + small);
  CHECK(r.status == 1);
  CHECK(r.err.find("ellipsoid_small.ply: --init has 42 vertices") != std::string::npos);

  r = runCli("embed " + in + " --init " + in);
  CHECK(r.status == 1);
  CHECK(r.err.find("--init needs a file with vertex positions") != std::string::npos);

  const std::string two = (dir() / "two.off").string();
  std::ofstream(two) << "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n";
  r = runCli("embed " + two);
  CHECK(r.status == 1);
  CHECK(r.err.find("2 connected components") != std::string::npos);

  r = runCli("embed " + (dir() / "missing.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("missing.ply") != std::string::npos);

  // A command-line mistake (here a failed range validator) is a malformed command line: exit status 2 (docs/cli.md),
  // with CLI11's message naming the option.
  r = runCli("embed " + in + " --tolerance -1");
  CHECK(r.status == 2);
  CHECK(r.err.find("--tolerance") != std::string::npos);
}
