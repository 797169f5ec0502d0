// End-to-end tests of `conformesh remesh MESHFILE`: CGAL's genus-2 eight.off remeshed to PLY (edge lengths, input face
// and barycentric coordinates per vertex) and VTK, the JSON report (Gauss–Bonnet, inverted triangles, the curvature
// check against the input's own deficits), the same in the input's own metric (`--refine-in input`, every angle of
// the file ≥ 20.7°), and one-line errors for a bad mesh file or options.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/io/mesh_io.h"

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
const std::string kEight = std::string(CONFORMESH_TEST_DATA_DIR) + "/eight.off";
}  // namespace

TEST_CASE("remesh MESHFILE: eight.off to PLY and VTK with the JSON report") {
  const fs::path out = dir() / "eight_remeshed.ply", vtk = dir() / "eight_remeshed.vtk";
  const Run r = runCli("-q remesh " + kEight + " --eps 0.03 -o " + out.string() + " --vtk " + vtk.string() + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["input_mesh"]["vertices"] == 315);
  CHECK(j["uniformization"]["target"] == "hyperbolic");
  CHECK(j["inverted_triangles"] == 0);
  CHECK(std::abs(j["quality"]["gauss_bonnet_residual"].get<double>()) < 1e-9);
  CHECK(j["quality_uniformized"]["min_angle_deg"].get<double>() >= 20.7);
  CHECK(std::abs(j["gaussian_curvature_measure"]["smooth_total_curvature"].get<double>() + 4 * M_PI) < 1e-9);
  // The file: the output's own lengths, positions on the input, and each vertex's input face.
  const MeshData d = readMesh(out.string());
  CHECK(d.nVertices == j["quality"]["vertices"].get<int>());
  CHECK(!d.positions.empty());
  CHECK(d.edges.size() == 3 * d.faces.size() / 2);
  for (const char* p : {"input_face", "input_b0", "input_b1", "input_b2", "lambda", "curvature", "error"})
    CHECK(d.vertexProperties.count(p) == 1);
  // The first 315 vertices are the input's: face and barycentric coordinates pick one of its corners.
  const auto& b0 = d.vertexProperties.at("input_b0");
  const auto& b1 = d.vertexProperties.at("input_b1");
  const auto& b2 = d.vertexProperties.at("input_b2");
  for (int v = 0; v < 315; ++v) CHECK(std::max({b0[v], b1[v], b2[v]}) == 1.0);
  // Read back as a triangulation, the file's lengths satisfy Gauss–Bonnet for χ = −2.
  CHECK(std::abs(curvatureTotals(toTriangulation(d)).gaussBonnetResidual) < 1e-9);
  CHECK(fs::file_size(vtk) > 0);
}

TEST_CASE("remesh MESHFILE --refine-in input: every angle of the file's own lengths at least 20.7 deg") {
  for (const char* mesh : {"eight.off", "cow.off"}) {
    INFO(mesh);
    const std::string path = std::string(CONFORMESH_TEST_DATA_DIR) + "/" + mesh;
    const fs::path out = dir() / (std::string(mesh) + "_input_metric.ply");
    const Run r = runCli("-q remesh " + path + " --eps 0.02 --refine-in input -o " + out.string() + " --json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["refine_in"] == "input");
    CHECK(j["smoothing_passes"] == 0);  // unsmoothed by default, as for metric families
    CHECK(j.count("uniformization") == 0);
    CHECK(j["inverted_triangles"] == 0);
    CHECK(j["max_same_face_length_error"].get<double>() < 1e-9);
    // The file: the same properties as the uniformized route's, and its lengths alone meet Ruppert's bound.
    const MeshData d = readMesh(out.string());
    for (const char* p : {"input_face", "input_b0", "input_b1", "input_b2", "lambda", "curvature", "error"})
      CHECK(d.vertexProperties.count(p) == 1);
    CHECK(!d.positions.empty());
    const IntrinsicTriangulation t = toTriangulation(d);
    REQUIRE(t.mesh.nVertices() == j["quality"]["vertices"].get<int>());
    double smallest = 180;
    for (int f = 0; f < t.mesh.nFaces(); ++f)
      for (int k = 0; k < 3; ++k) {
        const double a = t.length(3 * f + k), b = t.length(3 * f + (k + 1) % 3), c = t.length(3 * f + (k + 2) % 3);
        // The corner between sides a and c (at corner k), opposite b, by the law of cosines.
        const double cosine = std::clamp((a * a + c * c - b * b) / (2 * a * c), -1.0, 1.0);
        smallest = std::min(smallest, std::acos(cosine) * 180 / M_PI);
      }
    CHECK(smallest >= 20.7);
    CHECK(std::abs(curvatureTotals(t).gaussBonnetResidual) < 1e-9);
    const double inputArea = j["input_mesh"]["area"].get<double>();
    CHECK(std::abs(totalArea(t) - inputArea) <= 1e-12 * inputArea);
  }
}

TEST_CASE("remesh MESHFILE: human-readable report") {
  const Run r = runCli("-q remesh " + kEight + " --eps 0.05 --no-check -o " + (dir() / "e.ply").string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("hyperbolic") != std::string::npos);
  CHECK(r.out.find("smallest angle, input metric") != std::string::npos);
  CHECK(r.out.find("Gauss-Bonnet residual") != std::string::npos);
}

TEST_CASE("remesh MESHFILE errors: one line naming the file and the element") {
  const fs::path bad = dir() / "fin.off";
  std::ofstream(bad) << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
  Run r = runCli("remesh " + bad.string() + " --eps 0.1 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("fin.off") != std::string::npos);
  CHECK(r.err.find("edge") != std::string::npos);
  r = runCli("remesh " + (dir() / "missing.off").string() + " --eps 0.1 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("missing.off") != std::string::npos);
  r = runCli("remesh " + kEight + " --eps 0 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("--eps") != std::string::npos);
  r = runCli("remesh " + kEight + " --eps 0.05 --refine-in input --uniform -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("--uniform") != std::string::npos);
  // A value outside --refine-in's set is a malformed command line: exit status 2 (docs/cli.md).
  r = runCli("remesh " + kEight + " --eps 0.05 --refine-in flat -o " + (dir() / "x.ply").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("--refine-in") != std::string::npos);
  r = runCli("remesh " + kEight + " --eps 0.05 --smoothing 1 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("--refine-in input") != std::string::npos);
  r = runCli("remesh sphere --eps 0.05 --refine-in input -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("mesh files") != std::string::npos);
}
