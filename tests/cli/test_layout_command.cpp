// End-to-end tests of `conformesh layout`: a generated torus of revolution (τ near the reduced i·r/√(R² − r²) in
// --json) and its PLY (six texcoords per face, every face counter-clockwise in them) and SVG; a genus-2 mesh's deck
// group (SU(1,1) generators, a relation of 8 letters with residual below 1e-9); a disk's unit circle; a sphere's
// balanced centroid; the PNG (matplotlib required); one-line errors naming the extension or the file.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

using Run = conformesh::testing::CliRun;

Run runCli(const std::string& args) {
  return conformesh::testing::runConformesh(args);
}
std::string meshFile(const std::string& name) {
  return std::string(CONFORMESH_TEST_DATA_DIR) + "/" + name;
}

}  // namespace

TEST_CASE("layout of a torus of revolution: periods and modulus, PLY texcoords, SVG") {
  const fs::path d = conformesh::testing::scratchDir();
  const std::string torus = (d / "torus.ply").string();
  REQUIRE(runCli("generate torus --R 1 --r 0.4 --n 50 --m 20 -o " + torus).status == 0);
  const Run r = runCli("layout " + torus + " -o " + (d / "torus-layout.ply").string() + " --json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["target"] == "flat-torus");
  const double exact = std::sqrt(1 - 0.16) / 0.4;  // Im of the reduced modulus, max(a, 1/a), a = r/√(R² − r²)
  CHECK(std::abs(j["tau"][0].get<double>()) < 0.02);
  CHECK(std::abs(j["tau"][1].get<double>() - exact) < 0.02);  // 50 × 20 grid: error ~1e-2 (order 2)
  CHECK(j["relation_residual"].get<double>() < 1e-12);
  // The PLY: header with the texcoord list, then per face "3 a b c 6 u0 v0 u1 v1 u2 v2", counter-clockwise.
  std::ifstream ply(d / "torus-layout.ply");
  std::string line;
  int faces = -1, vertices = -1;
  bool texcoord = false;
  while (std::getline(ply, line) && line != "end_header") {
    std::istringstream s(line);
    std::string w, what;
    s >> w;
    if (w == "element") {
      int n;
      s >> what >> n;
      (what == "face" ? faces : vertices) = n;
    }
    if (line == "property list uchar double texcoord") texcoord = true;
  }
  CHECK(texcoord);
  REQUIRE(vertices == 1000);
  REQUIRE(faces == 2000);
  for (int v = 0; v < vertices; ++v) std::getline(ply, line);
  int negative = 0;
  for (int f = 0; f < faces; ++f) {
    int three, a, b, c, six;
    double u[6];
    ply >> three >> a >> b >> c >> six >> u[0] >> u[1] >> u[2] >> u[3] >> u[4] >> u[5];
    REQUIRE((three == 3 && six == 6));
    if ((u[2] - u[0]) * (u[5] - u[1]) - (u[3] - u[1]) * (u[4] - u[0]) <= 0) ++negative;
  }
  CHECK(negative == 0);
  const Run svg = runCli("layout " + torus + " -o " + (d / "torus.svg").string());
  REQUIRE(svg.status == 0);
  CHECK(svg.out.find("modulus tau") != std::string::npos);
  const std::string text = conformesh::testing::slurp(d / "torus.svg");
  CHECK(text.find("<svg") != std::string::npos);
  CHECK(text.find("</svg>") != std::string::npos);
}

TEST_CASE("layout of a genus-2 surface prints its deck group and relation") {
  const fs::path d = conformesh::testing::scratchDir();
  const Run r =
      runCli("layout " + meshFile("double-torus-example.off") + " -o " + (d / "g2.svg").string() + " --json --tiles 2");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["target"] == "hyperbolic");
  REQUIRE(j["generators"].size() == 4);
  for (const auto& g : j["generators"]) {
    const double a2 = std::pow(g["a"][0].get<double>(), 2) + std::pow(g["a"][1].get<double>(), 2);
    const double b2 = std::pow(g["b"][0].get<double>(), 2) + std::pow(g["b"][1].get<double>(), 2);
    CHECK(std::abs(a2 - b2 - 1) < 1e-9);  // SU(1,1)
    CHECK(g["translation_length"].get<double>() > 0);
  }
  CHECK(j["relation_residual"].get<double>() < 1e-9);
  // "g1 g2^-1 ..." with 8 letters.
  std::istringstream letters(j["relation"].get<std::string>());
  int n = 0;
  for (std::string w; letters >> w;) ++n;
  CHECK(n == 8);
}

TEST_CASE("layout of a disk and a sphere, and PNG through matplotlib") {
  const fs::path d = conformesh::testing::scratchDir();
  const Run disk = runCli("layout " + meshFile("patch-01.off") + " -o " + (d / "patch.svg").string() + " --json");
  REQUIRE(disk.status == 0);
  const auto j = nlohmann::json::parse(disk.out);
  REQUIRE(j["circles"].size() == 1);
  CHECK(std::abs(j["circles"][0]["radius"].get<double>() - 1) < 1e-8);
  const Run sphere = runCli("layout " + meshFile("blobby.off") + " -o " + (d / "blobby.ply").string() + " --json");
  REQUIRE(sphere.status == 0);
  CHECK(nlohmann::json::parse(sphere.out)["centroid_distance"].get<double>() < 1e-11);
  // The README's commands (scripts/bootstrap.sh) install matplotlib for Debian's interpreter, which `layout` runs
  // first: its absence is a broken setup, not a reason to skip the PNG.
  INFO("the PNG needs matplotlib for /usr/bin/python3: apt-get install python3-matplotlib");
  REQUIRE(std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0);
  const Run png = runCli("layout " + meshFile("eight.off") + " -o " + (d / "eight.png").string());
  INFO(png.err);
  REQUIRE(png.status == 0);
  CHECK(conformesh::testing::slurp(d / "eight.png").substr(0, 8) == "\x89PNG\r\n\x1a\n");  // the PNG signature
}

TEST_CASE("layout errors are one line naming the problem") {
  const fs::path d = conformesh::testing::scratchDir();
  const Run ext = runCli("layout " + meshFile("eight.off") + " -o " + (d / "eight.jpg").string());
  CHECK(ext.status == 1);
  CHECK(ext.err.find("must end in .svg, .png or .ply, found '.jpg'") != std::string::npos);
  const Run missing = runCli("layout " + (d / "nope.off").string() + " -o " + (d / "x.svg").string());
  CHECK(missing.status == 1);
  CHECK(missing.err.find("nope.off") != std::string::npos);
}
