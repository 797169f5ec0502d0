// End-to-end tests of `conformesh layout`: a generated torus of revolution (τ near the reduced i·r/√(R² − r²) in
// --json) and its PLY (six texcoords per face, every face counter-clockwise in them) and SVG; a genus-2 mesh's deck
// group (SU(1,1) generators, a relation of 8 letters with residual below 1e-9); a disk's unit circle; a sphere's
// balanced centroid; the PNG (matplotlib required); one-line errors naming the extension or the file.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"
#include "support/svg_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"

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
  std::vector<std::array<double, 6>> texcoords(faces);
  for (int f = 0; f < faces; ++f) {
    int three, a, b, c, six;
    double* u = texcoords[f].data();
    ply >> three >> a >> b >> c >> six >> u[0] >> u[1] >> u[2] >> u[3] >> u[4] >> u[5];
    REQUIRE((three == 3 && six == 6));
    if ((u[2] - u[0]) * (u[5] - u[1]) - (u[3] - u[1]) * (u[4] - u[0]) <= 0) ++negative;
  }
  CHECK(negative == 0);
  const Run svg = runCli("layout " + torus + " -o " + (d / "torus.svg").string());
  REQUIRE(svg.status == 0);
  CHECK(svg.out.find("modulus tau") != std::string::npos);
  // The SVG's geometry: a 900 px picture (the default), one filled triangle per face and tile (D and its 8 translates,
  // --tiles 1), every corner inside the viewBox, D drawn last in its own group, and D's triangles the image of the
  // PLY's texcoords (the same layout) under one map (x, y) ↦ (a + s x, b − s y) — y up, one scale — to the 0.005 px of
  // the printed decimals (the fit's own error is far below that).
  const conformesh::testing::SvgPicture pic = conformesh::testing::readSvg(conformesh::testing::slurp(d / "torus.svg"));
  CHECK(pic.viewBox == std::array<double, 4>{0, 0, 900, 900});
  std::vector<const conformesh::testing::SvgShape*> triangles;
  for (const auto& sh : pic.shapes)
    if (sh.fill != "none") triangles.push_back(&sh);
  REQUIRE(triangles.size() == 9u * faces);
  int outside = 0;
  for (const auto* t : triangles) {
    REQUIRE(t->points.size() == 3);
    for (const auto& p : t->points) outside += (p[0] >= 0 && p[0] <= 900 && p[1] >= 0 && p[1] <= 900) ? 0 : 1;
  }
  CHECK(outside == 0);
  const std::size_t first = triangles.size() - faces;  // D, after the tiles
  CHECK(triangles[first]->groupStroke != triangles[first - 1]->groupStroke);
  for (std::size_t i = first; i < triangles.size(); ++i) CHECK(triangles[i]->groupStroke == triangles[first]->groupStroke);
  // Least-squares fit of px = a + s u and py = b − s' v over D's corners; s' must equal s.
  auto fit = [&](int axis, double sign) {
    double su = 0, sp = 0, suu = 0, sup = 0, n = 0;
    for (int f = 0; f < faces; ++f)
      for (int k = 0; k < 3; ++k) {
        const double u = sign * texcoords[f][2 * k + axis], p = triangles[first + f]->points[k][axis];
        su += u, sp += p, suu += u * u, sup += u * p, n += 1;
      }
    const double slope = (n * sup - su * sp) / (n * suu - su * su);
    const double offset = (sp - slope * su) / n;
    double worst = 0, lo = 1e300, hi = -1e300;
    for (int f = 0; f < faces; ++f)
      for (int k = 0; k < 3; ++k) {
        const double p = triangles[first + f]->points[k][axis];
        worst = std::max(worst, std::abs(offset + slope * sign * texcoords[f][2 * k + axis] - p));
        lo = std::min(lo, p), hi = std::max(hi, p);
      }
    return std::array<double, 3>{slope, worst, hi - lo};
  };
  const auto [sx, ex, wx] = fit(0, 1);
  const auto [sy, ey, wy] = fit(1, -1);
  INFO("scale " << sx << " and " << sy << " px per unit, largest corner offsets " << ex << ", " << ey
                << " px, D spans " << wx << " × " << wy << " px");
  CHECK(sx > 0);
  // Rounding to 0.01 px moves a fitted slope by at most 0.01 px over the extent fitted, relatively.
  CHECK(sy == Approx(sx).epsilon(0.01 / wx + 0.01 / wy));
  CHECK(ex <= 0.0051);
  CHECK(ey <= 0.0051);
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
  // The SVG: the Poincaré disk's unit circle, one filled triangle per face of D and of each of its images under the
  // 64 reduced words of length 1 and 2 in 4 generators (8 + 8·7), every corner inside the circle (to the 0.01 px of
  // the printed coordinates).
  const int nf = static_cast<int>(conformesh::intrinsic::readMesh(meshFile("double-torus-example.off")).faces.size());
  const conformesh::testing::SvgPicture pic = conformesh::testing::readSvg(conformesh::testing::slurp(d / "g2.svg"));
  REQUIRE(pic.circles.size() == 1);
  const auto c = pic.circles[0];
  CHECK(c.cx == Approx(pic.viewBox[2] / 2));
  CHECK(c.cy == Approx(pic.viewBox[3] / 2));
  CHECK(c.r == Approx(0.47 * pic.viewBox[2]));  // the picture's box is the circle's, [−1, 1]², with a 3 % margin
  std::size_t filled = 0;
  double farthest = 0;
  for (const auto& sh : pic.shapes) {
    filled += sh.fill != "none" ? 1 : 0;
    for (const auto& p : sh.points) farthest = std::max(farthest, std::hypot(p[0] - c.cx, p[1] - c.cy));
  }
  CHECK(filled == 65u * nf);
  CHECK(farthest <= c.r + 0.01);
}

TEST_CASE("layout of a disk and a sphere, and PNG through matplotlib") {
  const fs::path d = conformesh::testing::scratchDir();
  const Run disk = runCli("layout " + meshFile("patch-01.off") + " -o " + (d / "patch.svg").string() + " --json");
  REQUIRE(disk.status == 0);
  const auto j = nlohmann::json::parse(disk.out);
  REQUIRE(j["circles"].size() == 1);
  CHECK(std::abs(j["circles"][0]["radius"].get<double>() - 1) < 1e-8);
  // The SVG: one filled triangle per face, the boundary circle as one closed unfilled polygon of 256 points at a common
  // distance from their centroid (the circle's centre), every corner inside it (to the printed 0.01 px).
  {
    const conformesh::testing::SvgPicture pic =
        conformesh::testing::readSvg(conformesh::testing::slurp(d / "patch.svg"));
    std::vector<const conformesh::testing::SvgShape*> filled, outlines;
    for (const auto& sh : pic.shapes) (sh.fill == "none" ? outlines : filled).push_back(&sh);
    CHECK(filled.size() == static_cast<std::size_t>(conformesh::intrinsic::readMesh(meshFile("patch-01.off")).faces.size()));
    REQUIRE(outlines.size() == 1);
    REQUIRE(outlines[0]->tag == "polygon");
    REQUIRE(outlines[0]->points.size() == 256);
    double cx = 0, cy = 0;
    for (const auto& p : outlines[0]->points) cx += p[0] / 256, cy += p[1] / 256;
    double rmin = 1e300, rmax = 0, farthest = 0;
    for (const auto& p : outlines[0]->points) {
      rmin = std::min(rmin, std::hypot(p[0] - cx, p[1] - cy));
      rmax = std::max(rmax, std::hypot(p[0] - cx, p[1] - cy));
    }
    for (const auto* t : filled)
      for (const auto& p : t->points) farthest = std::max(farthest, std::hypot(p[0] - cx, p[1] - cy));
    CHECK(rmax - rmin < 0.02);
    CHECK(rmin == Approx(0.47 * pic.viewBox[2]).epsilon(1e-4));
    CHECK(farthest <= rmax + 0.01);
  }
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
