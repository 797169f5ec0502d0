// End-to-end tests of CLI options no other test passes (issue #19 item 4): `uniformize` with --method, --tolerance,
// --max-steps and --correspondence (the flip log's format and Ptolemy relation); `convergence` with --vertices,
// --levels, --ratio, --t0-resolution, --no-plot and its JSON table; `generate --json`, `--perturb --seed`
// reproducibility and `--ascii`; `refine` with --boundary, --off-centers, --max-insertions and --ascii. Each case
// checks a mathematical or documented property of the output, not only the exit status.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"
#include "support/gauss_bonnet_bound.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/curvature.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;
using conformesh::testing::runConformesh;
using conformesh::testing::slurp;

namespace {
fs::path dir() {
  return conformesh::testing::scratchDir();
}
std::string at(const std::string& name) {
  return (dir() / name).string();
}
// max |Σθ − 2π| over interior vertices, from a file's own lengths.
double worstInteriorAngleSum(const IntrinsicTriangulation& t) {
  const std::vector<double> k = vertexCurvatures(t);
  double worst = 0;
  for (int v = 0; v < t.mesh.nVertices(); ++v)
    if (!t.mesh.isBoundaryVertex(v)) worst = std::max(worst, std::abs(k[v]));
  return worst;
}
}  // namespace

TEST_CASE("uniformize --method circle-packing --tolerance --max-steps on a torus: flat to the tolerance asked") {
  REQUIRE(runConformesh("-q generate torus --n 12 --m 8 -o " + at("torus.ply")).status == 0);
  const auto r = runConformesh("-q uniformize " + at("torus.ply") + " -o " + at("torus_cp.ply") +
                               " --method circle-packing --tolerance 1e-9 --max-steps 40 --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["method"] == "circle-packing");
  CHECK(j["target"] == "flat-torus");
  CHECK(j["genus"] == 1);
  CHECK(j["newton_steps"].get<int>() <= 40);
  CHECK(j["max_curvature_residual"].get<double>() < 1e-9);  // the documented stopping rule max |K − K̂| < T
  CHECK(j["flips"] == 0);                                   // circle packing does not flip (docs/cli.md)
  // The written lengths are flat: every vertex (the torus has no boundary) has angle sum 2π to the tolerance.
  const IntrinsicTriangulation t = toTriangulation(readMesh(at("torus_cp.ply")));
  CHECK(worstInteriorAngleSum(t) < 1e-9);
  // --max-steps 1 cannot reach 1e-14: the documented non-convergence error, exit status 1, naming the residual.
  const auto capped = runConformesh("-q uniformize " + at("torus.ply") + " -o " + at("torus_1.ply") +
                                    " --method inversive-distance --tolerance 1e-14 --max-steps 1");
  CHECK(capped.status == 1);
  CHECK(capped.err.find("converge") != std::string::npos);
  CHECK(!fs::exists(at("torus_1.ply")));
}

TEST_CASE("uniformize --correspondence: the flip log's format, its faces and the Ptolemy relation of every flip") {
  REQUIRE(runConformesh("-q generate genus --g 0 --resolution 3 -o " + at("box.ply")).status == 0);
  const auto r = runConformesh("-q uniformize " + at("box.ply") + " -o " + at("box_u.ply") + " --correspondence " +
                               at("box_map.json") + " --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["method"] == "yamabe");
  CHECK(j["target"] == "sphere");
  const auto map = nlohmann::json::parse(slurp(at("box_map.json")));
  CHECK(map["format"] == "conformesh flow correspondence 1");
  const MeshData out = readMesh(at("box_u.ply"));
  CHECK(map["faces"].get<std::size_t>() == out.faces.size());
  CHECK(map["flip_fields"].size() == 10);
  const auto& flips = map["flips"];
  REQUIRE(flips.size() > 0);
  // Not checked: that the log's length equals the report's "flips" (measured 192 against 191 on this box; docs/cli.md
  // does not define the relation — reported on issue #19).
  int ptolemyChecked = 0;
  for (const auto& f : flips) {
    REQUIRE(f.size() == 10);
    const int faces = map["faces"].get<int>();
    CHECK((f[0].get<int>() >= 0 && f[0].get<int>() < faces && f[1].get<int>() >= 0 && f[1].get<int>() < faces));
    CHECK((f[2].get<int>() >= 0 && f[2].get<int>() < 3 && f[3].get<int>() >= 0 && f[3].get<int>() < 3));
    // Penner lengths obey Ptolemy across the flipped quad (a c b d): ab·cd = ca·db + bc·ad, to 1e-12 relative (the
    // few roundings of one product and one quotient, and the 17 digits JSON keeps).
    const double ab = f[4], bc = f[5], ca = f[6], ad = f[7], db = f[8], cd = f[9];
    CHECK(ab * cd == Approx(ca * db + bc * ad).epsilon(1e-12));
    ++ptolemyChecked;
  }
  CHECK(ptolemyChecked == static_cast<int>(flips.size()));
}

TEST_CASE("convergence --vertices --ratio --t0-resolution --no-plot --json: the table, the bounds and R ~ V^(-1/2)") {
  const std::string prefix = at("conv");
  const auto r = runConformesh(
      "-q convergence sphere --vertices 300,600,1200 --ratio 1.6 --t0-resolution 6 "
      "--no-plot --json -o " +
      prefix);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["ratio_bound"].get<double>() == 1.6);
  REQUIRE(j["levels"].size() == 3);
  const int targets[] = {300, 600, 1200};
  for (int i = 0; i < 3; ++i) {
    const auto& L = j["levels"][i];
    CHECK(L["target_vertices"] == targets[i]);
    // Closed genus 0: Euler's formula F = 2V − 4.
    CHECK(L["triangles"].get<int>() == 2 * L["vertices"].get<int>() - 4);
    CHECK(L["quality"]["max_radius_edge_ratio"].get<double>() <= 1.6 * (1 + 1e-9));
    CHECK(L["quality"]["min_angle_deg"].get<double>() >= std::asin(1 / (2 * 1.6)) * 180 / M_PI - 1e-7);
    CHECK(std::abs(L["total_area"].get<double>() - 4 * M_PI) < 0.02 * 4 * M_PI);
  }
  // Mesh size on a fixed area: mean R ~ V^(−1/2); the fitted slope over a factor 4 in V within ±0.1.
  CHECK(j["orders"]["mean_circumradius_vs_vertices"].get<double>() == Approx(-0.5).margin(0.1));
  // --no-plot: the CSV and JSON only, and PREFIX.json is the report (with the per-vertex errors).
  CHECK(j["written"].size() == 2);
  CHECK(!fs::exists(prefix + "_fig10.png"));
  const auto file = nlohmann::json::parse(slurp(prefix + ".json"));
  CHECK(file["levels"] == j["levels"]);
  CHECK(file.contains("finest_relative_errors"));
  const std::string csv = slurp(prefix + ".csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 4);  // a header and one row per level
}

TEST_CASE("convergence --levels 3: the first three vertex counts of the paper's Table 2") {
  const auto r = runConformesh("-q convergence sphere --levels 3 --no-plot --json -o " + at("conv3"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["levels"].size() == 3);
  CHECK(j["levels"][0]["target_vertices"] == 1021);  // Li et al. 2013, Table 2: T1, T2, T3
  CHECK(j["levels"][1]["target_vertices"] == 2045);
  CHECK(j["levels"][2]["target_vertices"] == 4093);
}

TEST_CASE("convergence refuses levels that repeat T0 (exit 2, the level and the fix) and the fix gives finer levels") {
  // T0 at the default resolution 10 is the icosphere of 10·10² + 2 = 1002 vertices; refinement only adds vertices, so
  // the targets 500 and 1k both give T0 itself: a fit over them would repeat a point. Nothing is written.
  const std::string prefix = at("conv_repeat");
  const std::string study = "-q convergence kerr-newman --param a=0.99 --vertices 500,1k,2k,4k --no-plot ";
  const auto r = runConformesh(study + "-o " + prefix);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("conformesh: error: convergence: level 2 (target 1000 vertices) is not finer "
                                      "than level 1: 1002 vertices"));
  CHECK_THAT(r.err, Catch::Contains("T0, of 1002 vertices (resolution 10)"));
  // The suggested T0: the finest icosphere of at most 500 / 2 vertices, resolution 4 (162); or targets ≥ 2·1002.
  CHECK_THAT(r.err, Catch::Contains("--t0-resolution 4 (a T0 of 162 vertices") &&
                        Catch::Contains("targets from 2004 vertices up"));
  CHECK(!fs::exists(prefix + ".csv"));
  CHECK(!fs::exists(prefix + ".json"));

  const auto fixed = runConformesh(study + "--t0-resolution 4 --json -o " + prefix);
  INFO(fixed.err);
  REQUIRE(fixed.status == 0);
  const auto j = nlohmann::json::parse(fixed.out);
  CHECK(j["t0_vertices"] == 162);
  REQUIRE(j["levels"].size() == 4);
  for (int i = 1; i < 4; ++i) {  // every level strictly finer than the one before
    const auto &L = j["levels"][i], &P = j["levels"][i - 1];
    CHECK(L["vertices"].get<int>() > P["vertices"].get<int>());
    CHECK(L["quality"]["mean_circumradius"].get<double>() < P["quality"]["mean_circumradius"].get<double>());
  }
  // Four distinct levels over a factor ~7 in V: mean R ~ V^(−1/2) within ±0.1, e_G of order ≥ 1 (Theorem 3.4).
  CHECK(j["orders"]["mean_circumradius_vs_vertices"].get<double>() == Approx(-0.5).margin(0.1));
  CHECK(j["orders"]["e_G_vs_mean_circumradius"].get<double>() >= 0.9);
}

TEST_CASE("generate --json, --perturb --seed and --ascii: counts, reproducible bytes, bounded perturbation") {
  const auto g = runConformesh("-q generate icosphere --level 2 -o " + at("ico.ply") + " --json");
  REQUIRE(g.status == 0);
  const auto j = nlohmann::json::parse(g.out);
  // Icosahedron subdivided L = 2 times: V = 10·4^L + 2, F = 20·4^L, χ = 2.
  CHECK(j.dump().find("162") != std::string::npos);
  const MeshData plain = readMesh(at("ico.ply"));
  CHECK(plain.nVertices == 162);
  CHECK(plain.faces.size() == 320);
  auto perturbed = [&](const std::string& name, int seed, bool ascii) {
    const auto r = runConformesh("-q generate icosphere --level 2 --perturb 0.1 --seed " + std::to_string(seed) +
                                 (ascii ? " --ascii" : "") + " -o " + at(name));
    REQUIRE(r.status == 0);
    return slurp(at(name));
  };
  const std::string a = perturbed("p7a.ply", 7, false), b = perturbed("p7b.ply", 7, false);
  const std::string c = perturbed("p8.ply", 8, false), text = perturbed("p7.txt.ply", 7, true);
  CHECK(a == b);  // same seed, same file, byte for byte
  CHECK(a != c);
  CHECK(text.rfind("ply\nformat ascii 1.0\n", 0) == 0);
  CHECK(a.find("format binary_little_endian 1.0") != std::string::npos);
  // Lengths times (1 + 0.1·t), t in (−1, 1): every ratio to the plain chord within (0.9, 1.1), not all 1; the ASCII
  // file carries the same metric (17 significant digits).
  const MeshData p = readMesh(at("p7a.ply")), q = readMesh(at("p7.txt.ply"));
  const IntrinsicTriangulation t0 = toTriangulation(plain), t1 = toTriangulation(p), t2 = toTriangulation(q);
  REQUIRE(t1.edgeLengths.size() == t0.edgeLengths.size());
  double lo = 2, hi = 0;
  for (std::size_t e = 0; e < t0.edgeLengths.size(); ++e) {
    const double ratio = t1.edgeLengths[e] / t0.edgeLengths[e];
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
    CHECK(t2.edgeLengths[e] == Approx(t1.edgeLengths[e]).epsilon(1e-15));
  }
  CHECK(lo > 0.9);
  CHECK(hi < 1.1);
  CHECK(hi - lo > 0.1);  // 480 uniform draws span most of (0.9, 1.1)
}

TEST_CASE("refine --boundary --off-centers --ascii, and --max-insertions stopping with an error") {
  REQUIRE(runConformesh("-q generate disk --rings 3 -o " + at("disk.ply")).status == 0);
  const double eps = 0.08, B = std::sqrt(2.0);
  for (const char* boundary : {"circle", "geodesic"}) {
    INFO(boundary);
    const std::string out = at(std::string("disk_") + boundary + ".ply");
    const auto r = runConformesh("-q refine " + at("disk.ply") + " --eps 0.08 --off-centers --ascii --boundary " +
                                 boundary + " --json -o " + out);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(slurp(out).rfind("ply\nformat ascii 1.0\n", 0) == 0);
    const IntrinsicTriangulation t = toTriangulation(readMesh(out));
    CHECK(t.mesh.eulerCharacteristic() == 1);
    // Off-centres keep the guarantees: circumradius ≤ ε and the shape bound, from the file's own lengths.
    double maxR = 0, worstRatio = 0;
    for (int f = 0; f < t.mesh.nFaces(); ++f) {
      const double a = t.length(3 * f), b = t.length(3 * f + 1), c = t.length(3 * f + 2);
      const double R = a * b * c / std::sqrt((a + b + c) * (b + c - a) * (c + a - b) * (a + b - c));
      maxR = std::max(maxR, R);
      worstRatio = std::max(worstRatio, R / std::min({a, b, c}));
    }
    CHECK(maxR <= eps * (1 + 1e-9));
    CHECK(worstRatio <= B * (1 + 1e-9));
    CHECK(std::abs(curvatureTotals(t).gaussBonnetResidual) <=
          conformesh::testing::gaussBonnetRoundoff(t.mesh.nFaces()));
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.dump().find("insert") != std::string::npos);
  }
  const auto capped =
      runConformesh("-q refine " + at("disk.ply") + " --eps 0.02 --max-insertions 5 -o " + at("disk_capped.ply"));
  CHECK(capped.status == 1);
  CHECK(capped.err.find("5") != std::string::npos);
  CHECK(!fs::exists(at("disk_capped.ply")));
}
