// End-to-end tests of `conformesh remesh MESHFILE`: CGAL's genus-2 eight.off remeshed to PLY (edge lengths, input face
// and barycentric coordinates per vertex) and VTK, the JSON report (Gauss–Bonnet, inverted triangles, the curvature
// check against the input's own deficits) on the uniformized route (`--refine-in uniformized`, explicit), the same in
// the input's own metric (the default route, `--refine-in input`: every angle of the file ≥ 20.7°), and one-line
// errors for a bad mesh file or options.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"
#include "support/vtk_reader.h"
#include "support/gauss_bonnet_bound.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <sstream>
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

TEST_CASE("remesh MESHFILE --refine-in uniformized: eight.off to PLY and VTK with the JSON report") {
  const fs::path out = dir() / "eight_remeshed.ply", vtk = dir() / "eight_remeshed.vtk";
  const Run r = runCli("-q remesh " + kEight + " --eps 0.03 --refine-in uniformized -o " + out.string() + " --vtk " +
                       vtk.string() + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["refine_in"] == "uniformized");  // the paper's route, reachable explicitly (not the default)
  CHECK(j["input_mesh"]["vertices"] == 315);
  CHECK(j["uniformization"]["target"] == "hyperbolic");
  CHECK(j["inverted_triangles"] == 0);
  CHECK(std::abs(j["quality"]["gauss_bonnet_residual"].get<double>()) <= conformesh::testing::gaussBonnetRoundoff(j["quality"]["triangles"].get<int>()));
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
  CHECK(std::abs(curvatureTotals(toTriangulation(d)).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(d.faces.size()));
  // The VTK of the same run, parsed back: the PLY's positions and faces, and every per-vertex field of the PLY except
  // the input_* correspondence, one value per point, all bit for bit (both files print doubles to 17 digits or as
  // binary; a non-finite value is written to VTK as nan).
  const conformesh::testing::VtkPolyData v = conformesh::testing::readVtkPolyData(vtk.string());
  REQUIRE(v.points.size() == d.positions.size());
  int pointsDiffer = 0;
  for (std::size_t i = 0; i < v.points.size(); ++i)
    for (int k = 0; k < 3; ++k) pointsDiffer += v.points[i][k] == d.positions[i][k] ? 0 : 1;
  CHECK(pointsDiffer == 0);
  REQUIRE(v.polygons.size() == d.faces.size());
  int facesDiffer = 0;
  for (std::size_t f = 0; f < d.faces.size(); ++f)
    facesDiffer += v.polygons[f] == std::vector<int>(d.faces[f].begin(), d.faces[f].end()) ? 0 : 1;
  CHECK(facesDiffer == 0);
  CHECK(v.cellData.empty());
  std::vector<std::string> expected;
  for (const auto& [name, values] : d.vertexProperties)
    if (name.rfind("input_", 0) != 0) expected.push_back(name);
  std::vector<std::string> found;
  for (const auto& [name, values] : v.pointData) found.push_back(name);
  CHECK(found == expected);
  CHECK(v.pointData.count("error") == 1);  // the per-vertex relative error of the curvature measure, for colouring
  for (const auto& [name, values] : v.pointData) {
    if (!d.vertexProperties.count(name)) continue;
    const auto& ply = d.vertexProperties.at(name);
    REQUIRE(values.size() == ply.size());
    int differ = 0;
    for (std::size_t i = 0; i < ply.size(); ++i)
      differ += (std::isfinite(ply[i]) ? values[i] == ply[i] : std::isnan(values[i])) ? 0 : 1;
    INFO("field " << name);
    CHECK(differ == 0);
  }
}

TEST_CASE("remesh MESHFILE, default route (input): every angle of the file's own lengths at least 20.7 deg") {
  // The default for a mesh file is the input route (issue #18 item 6): eight.off without --refine-in, cow.off with
  // it spelt out; arcsin(1 / (2√2)) = 20.70° is Ruppert's bound at the default B = √2.
  for (const char* mesh : {"eight.off", "cow.off"}) {
    INFO(mesh);
    const std::string path = std::string(CONFORMESH_TEST_DATA_DIR) + "/" + mesh;
    const fs::path out = dir() / (std::string(mesh) + "_input_metric.ply");
    const std::string route = std::string(mesh) == "eight.off" ? "" : " --refine-in input";
    const Run r = runCli("-q remesh " + path + " --eps 0.02" + route + " -o " + out.string() + " --json");
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
    CHECK(std::abs(curvatureTotals(t).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(t.mesh.nFaces()));
    const double inputArea = j["input_mesh"]["area"].get<double>();
    CHECK(std::abs(totalArea(t) - inputArea) <= 1e-12 * inputArea);
  }
}

TEST_CASE("remesh MESHFILE: human-readable report") {
  const std::string args =
      "-q remesh " + kEight + " --eps 0.05 --refine-in uniformized --no-check -o " + (dir() / "e.ply").string();
  const Run r = runCli(args);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("hyperbolic") != std::string::npos);
  // Its figures against the JSON report of the same command (the run is deterministic: the flow's two-thread loops
  // split their work into fixed ranges), each to the precision it is printed with.
  const Run rj = runCli(args + " --json");
  REQUIRE(rj.status == 0);
  const auto j = nlohmann::json::parse(rj.out);
  const auto& q = j["quality"];
  // The text after a line's label (labels are padded to one column), or "" when no line starts with it.
  auto after = [&](const std::string& label) {
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
      const auto start = line.find_first_not_of(' ');
      if (start != std::string::npos && line.compare(start, label.size(), label) == 0)
        return line.substr(start + label.size());
    }
    return std::string();
  };
  // |printed − json| within half a unit of the printed value's last digit (%g with `digits` significant digits).
  auto agrees = [](double printed, double json, int digits) {
    const double unit = json == 0 ? 0 : std::pow(10.0, std::floor(std::log10(std::abs(json))) - (digits - 1));
    return std::abs(printed - json) <= 0.5 * unit * (1 + 1e-9);
  };
  double a = 0, b = 0;
  long n = 0, m = 0;
  INFO(r.out);
  REQUIRE(std::sscanf(after("output").c_str(), "%ld vertices, %ld triangles", &n, &m) == 2);
  CHECK(n == q["vertices"].get<long>());
  CHECK(m == q["triangles"].get<long>());
  REQUIRE(std::sscanf(after("smallest angle, input metric").c_str(), "%lf deg (mean per triangle %lf deg)", &a, &b) ==
          2);
  CHECK(agrees(a, q["min_angle_deg"].get<double>(), 5));
  CHECK(agrees(b, q["mean_min_angle_deg"].get<double>(), 5));
  REQUIRE(std::sscanf(after("circumradius, input metric").c_str(), " max %lf, mean %lf", &a, &b) == 2);
  CHECK(agrees(a, q["max_circumradius"].get<double>(), 6));
  CHECK(agrees(b, q["mean_circumradius"].get<double>(), 6));
  REQUIRE(std::sscanf(after("inverted triangles on the input").c_str(), "%ld of %ld checked", &n, &m) == 2);
  CHECK(n == j["inverted_triangles"].get<long>());
  CHECK(m == j["orientation_checked_triangles"].get<long>());
  REQUIRE(std::sscanf(after("length vs located ends (one face)").c_str(), " max relative difference %lf over %ld edges",
                      &a, &n) == 2);
  CHECK(agrees(a, j["max_same_face_length_error"].get<double>(), 3));
  CHECK(n == j["same_face_edges"].get<long>());
  REQUIRE(std::sscanf(after("Gauss-Bonnet residual").c_str(), "%lf", &a) == 1);
  CHECK(agrees(a, q["gauss_bonnet_residual"].get<double>(), 4));
  REQUIRE(std::sscanf(after("total area").c_str(), "%lf (input %lf)", &a, &b) == 2);
  CHECK(agrees(a, j["total_area"].get<double>(), 10));
  CHECK(agrees(b, j["input_mesh"]["area"].get<double>(), 10));
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
  // --uniform belongs to the uniformized route, which is not the default: the message names the switch.
  r = runCli("remesh " + kEight + " --eps 0.05 --uniform -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("--refine-in uniformized") != std::string::npos);
  r = runCli("remesh " + kEight + " --eps 0.05 --refine-in uniformized --smoothing 1 -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("--refine-in input") != std::string::npos);
  r = runCli("remesh sphere --eps 0.05 --refine-in input -o " + (dir() / "x.ply").string());
  CHECK(r.status == 1);
  CHECK(r.err.find("mesh files") != std::string::npos);
}

// CGAL's blobby_3cc.off (three connected components: two disks and an annulus) and horizons.off (two disks): each
// component is uniformized to its own target and remeshed alone; the merged file carries `component`, the report one
// entry per component.
TEST_CASE("several components: blobby_3cc.off and horizons.off summarized, uniformized and remeshed per component") {
  const std::string blobby = std::string(CONFORMESH_TEST_DATA_DIR) + "/blobby_3cc.off";
  const Run info = runCli("-q info " + blobby + " --json");
  REQUIRE(info.status == 0);
  const auto ji = nlohmann::json::parse(info.out);
  REQUIRE(ji["components"].size() == 3);
  double blobbyArea = 0;
  for (const auto& c : ji["components"]) {
    blobbyArea += c["total_area"].get<double>();
    // 2πχ of each component alone, to the round-off of its faces.
    CHECK(std::abs(c["gauss_bonnet_residual"].get<double>()) <=
          conformesh::testing::gaussBonnetRoundoff(c["faces"].get<int>()));
  }
  CHECK(blobbyArea == Approx(ji["total_area"].get<double>()).epsilon(1e-12));

  const fs::path uni = dir() / "blobby_3cc_uniform.ply";
  const Run u = runCli("-q uniformize " + blobby + " -o " + uni.string() + " --json");
  INFO(u.err);
  REQUIRE(u.status == 0);
  const auto ju = nlohmann::json::parse(u.out);
  REQUIRE(ju["component_count"] == 3);
  for (const auto& c : ju["components"]) {
    const std::string target = c["target"];
    const int chi = c["euler_characteristic"];
    INFO("component " << c["component"] << " target " << target);
    CHECK(c["max_curvature_residual"].get<double>() <= c["tolerance"].get<double>());
    CHECK(std::abs(c["gauss_bonnet_residual"].get<double>()) <=
          conformesh::testing::gaussBonnetRoundoff(c["faces"].get<int>()));
    if (target == "sphere") CHECK(c["total_area"].get<double>() == Approx(4 * M_PI).epsilon(1e-9));
    if (chi == 2) CHECK(target == "sphere");
    if (chi == 0) CHECK((target == "circle-domain" || target == "flat-cylinder"));
  }
  const MeshData ud = readMesh(uni.string());
  REQUIRE(ud.vertexProperties.count("component") == 1);
  CHECK(ud.vertexProperties.at("component").back() == 2.0);

  // The uniformized route on all three components keeps the input's area to the check's 1e-9. It did not on the
  // annulus (component 2, 2 boundary loops: its hole's circle bulges into the domain, and the boundary vertices split
  // on it were mapped into input faces; docs/robustness.md), which exited 3 naming the component.
  const Run uniformized = runCli("-q remesh " + blobby + " --eps-rel 0.05 --refine-in uniformized -o " +
                                 (dir() / "blobby_3cc_u.ply").string() + " --json");
  INFO(uniformized.err);
  REQUIRE(uniformized.status == 0);
  CHECK(std::abs(nlohmann::json::parse(uniformized.out)["total_area"].get<double>() / ji["total_area"].get<double>() -
                 1) <= 1e-9);

  // Both routes on blobby_3cc (input route) and horizons.off (two disks, both routes).
  const std::string horizons = std::string(CONFORMESH_TEST_DATA_DIR) + "/horizons.off";
  const std::pair<std::string, std::string> runs[] = {
      {blobby, "input"}, {horizons, "uniformized"}, {horizons, "input"}};
  for (const auto& [file, route] : runs) {
    INFO(file << " route " << route);
    const Run in = runCli("-q info " + file + " --json");
    REQUIRE(in.status == 0);
    const double inputArea = nlohmann::json::parse(in.out)["total_area"].get<double>();
    const fs::path out = dir() / ("components_" + route + ".ply");
    const Run r =
        runCli("-q remesh " + file + " --eps-rel 0.05 --refine-in " + route + " -o " + out.string() + " --json");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    REQUIRE(j["components"].size() == j["component_count"].get<std::size_t>());
    double sum = 0;
    for (const auto& c : j["components"]) {
      sum += c["total_area"].get<double>();
      // Each component an exact retriangulation of its own input component.
      CHECK(c["total_area"].get<double>() == Approx(c["input_mesh"]["area"].get<double>()).epsilon(1e-9));
      CHECK(std::abs(c["quality"]["gauss_bonnet_residual"].get<double>()) <=
            conformesh::testing::gaussBonnetRoundoff(c["quality"]["triangles"].get<int>()));
      CHECK(c["inverted_triangles"] == 0);
    }
    CHECK(sum == Approx(j["total_area"].get<double>()).epsilon(1e-14));
    const MeshData d = readMesh(out.string());
    const IntrinsicTriangulation t = toTriangulation(d);
    // The merged file's area: the components' areas summed face by face in another order.
    CHECK(totalArea(t) == Approx(sum).epsilon(1e-12));
    CHECK(totalArea(t) == Approx(inputArea).epsilon(1e-9));
    CHECK(t.mesh.components().size() == j["component_count"].get<std::size_t>());
    CHECK(d.vertexProperties.count("component") == 1);
    CHECK(d.nVertices == j["output_mesh"]["vertices"].get<int>());
  }
}
