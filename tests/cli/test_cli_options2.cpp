// More end-to-end tests of CLI options that no other test passed (found by scripts/cli_option_coverage.py, CTest
// cli_option_coverage): the global --quiet; `generate` icosphere/disk --radius, annulus --r1 --r2, flat-torus
// --omega1 --omega2 --keep-basis, torus --alternate; `layout --centre-vertex --direction-vertex --pixels`; `view
// --vtu`; `repair --merge-tolerance --area-tolerance`; `generate genus --cell`; `discretize --chart-lengths`. Each
// case checks a closed form or a documented property of the output, not only the exit status.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"

using namespace conformesh::intrinsic;
using conformesh::testing::runConformesh;
using conformesh::testing::slurp;

namespace {
std::string at(const std::string& name) {
  return (conformesh::testing::scratchDir() / name).string();
}
// Smallest and largest distance of the file's vertices from the origin (z included).
std::pair<double, double> radiusRange(const std::string& file) {
  const MeshData m = readMesh(file);
  double lo = 1e300, hi = 0;
  for (const auto& p : m.positions) {
    lo = std::min(lo, p.norm());
    hi = std::max(hi, p.norm());
  }
  return {lo, hi};
}
// Vertex positions are written with 17 significant digits and generated in double precision: 1e-12 relative covers
// both the generator's round-off (a few ulps per normalization) and the text round trip.
constexpr double kWritten = 1e-12;
}  // namespace

TEST_CASE("the global --quiet silences the progress lines on stderr, nothing else") {
  const auto loud = runConformesh("generate icosphere -o " + at("loud.off"));
  const auto quiet = runConformesh("--quiet generate icosphere -o " + at("quiet.off"));
  REQUIRE(loud.status == 0);
  REQUIRE(quiet.status == 0);
  CHECK(loud.err.find("writing") != std::string::npos);
  CHECK(quiet.err.empty());
  CHECK(slurp(at("loud.off")) == slurp(at("quiet.off")));
}

TEST_CASE("generate --radius and --r1/--r2 set the radii the meshes are made with") {
  REQUIRE(runConformesh("generate icosphere --radius 2.5 -o " + at("ico.off")).status == 0);
  const auto [ilo, ihi] = radiusRange(at("ico.off"));
  CHECK(ilo == Approx(2.5).epsilon(kWritten));  // every vertex on the sphere of radius R
  CHECK(ihi == Approx(2.5).epsilon(kWritten));
  REQUIRE(runConformesh("generate disk --radius 3 -o " + at("disk.off")).status == 0);
  CHECK(radiusRange(at("disk.off")).second == Approx(3.0).epsilon(kWritten));  // boundary vertices on |x| = R
  REQUIRE(runConformesh("generate annulus --r1 0.3 --r2 2 -o " + at("ann.off")).status == 0);
  const auto [alo, ahi] = radiusRange(at("ann.off"));
  CHECK(alo == Approx(0.3).epsilon(kWritten));
  CHECK(ahi == Approx(2.0).epsilon(kWritten));
}

TEST_CASE("generate flat-torus --omega1 --omega2: area |Im(conj(w1) w2)|; --keep-basis keeps the obtuse grid") {
  // ω1 = 1, ω2 = 2.3 + 2i: area |1·2 − 0·2.3| = 2. The reduced basis is (1, 0.3 + 2i), whose triangle (sides 1,
  // |0.3 + 2i| = 2.02, |−0.7 + 2i| = 2.12) is acute; the given basis's triangle 0, 1, 2.3 + 2i has the angle at 1
  // between −1 and 1.3 + 2i: cos = −1.3/|1.3 + 2i| < 0, obtuse (acos(−0.545) = 123°).
  auto run = [&](const std::string& extra, const std::string& name) {
    const auto r = runConformesh("generate flat-torus --omega1 1,0 --omega2 2.3,2 " + extra + " -o " + at(name) +
                                 " --json");
    REQUIRE(r.status == 0);
    CHECK(nlohmann::json::parse(r.out)["known"]["area"].get<double>() == Approx(2.0).epsilon(1e-14));
    const auto info = runConformesh("info " + at(name) + " --json");
    REQUIRE(info.status == 0);
    const auto j = nlohmann::json::parse(info.out);
    CHECK(j["total_area"].get<double>() == Approx(2.0).epsilon(1e-12));  // from the written lengths
    CHECK(j["genus"] == 1);
    return j["max_corner_angle_deg"].get<double>();
  };
  const double reduced = run("", "ft.ply"), kept = run("--keep-basis", "ft-kept.ply");
  INFO("max corner angle: reduced basis " << reduced << "°, --keep-basis " << kept << "°");
  CHECK(reduced < 90);
  CHECK(kept > 120);
}

TEST_CASE("generate torus --alternate: the checkerboard of diagonals gives vertex degrees 4 and 8 instead of 6") {
  // One diagonal per quad: every vertex of the n × m grid has degree 6. Alternating diagonals (n, m even): a vertex
  // is a corner of four quads and lies on all four diagonals or none, so degrees 8 and 4, half each.
  for (bool alternate : {false, true}) {
    REQUIRE(runConformesh("generate torus " + std::string(alternate ? "--alternate " : "") + "-o " + at("t.off"))
                .status == 0);
    const MeshData m = readMesh(at("t.off"));
    std::vector<int> degree(m.positions.size(), 0);
    for (const auto& f : m.faces)
      for (int v : f) ++degree[v];  // closed surface: a vertex's degree is its number of faces
    const auto count = [&](int d) { return static_cast<int>(std::count(degree.begin(), degree.end(), d)); };
    const int d4 = count(4), d6 = count(6), d8 = count(8);
    const int n = static_cast<int>(degree.size());
    if (alternate) {
      CHECK(d4 == n / 2);
      CHECK(d8 == n / 2);
    } else {
      CHECK(d6 == n);
    }
  }
}

TEST_CASE("layout --centre-vertex --direction-vertex: the chosen vertex at 0, the other on the positive x axis") {
  REQUIRE(runConformesh("generate disk -o " + at("d.off")).status == 0);
  REQUIRE(runConformesh("layout " + at("d.off") + " -o " + at("d.ply") + " --centre-vertex 5 --direction-vertex 7")
              .status == 0);
  const MeshData m = readMesh(at("d.ply"));
  // Möbius normalization of the circle domain (docs/layout.md §6): exact up to round-off of a few disk automorphisms.
  CHECK(m.positions[5].norm() < 1e-12);
  CHECK(std::abs(m.positions[7].y()) < 1e-12);
  CHECK(m.positions[7].x() > 0);
  const auto bad = runConformesh("layout " + at("d.off") + " -o " + at("e.ply") + " --centre-vertex 100000");
  // A vertex index the mesh does not have is an input error of the library (docs/cli.md: exit status 1, the element
  // named), not a malformed command line (2).
  CHECK(bad.status == 1);
  CHECK(bad.err.find("100000") != std::string::npos);
}

TEST_CASE("view --vtu writes a VTU with the mesh's point and cell counts") {
  REQUIRE(runConformesh("generate disk -o " + at("v.off")).status == 0);
  const MeshData m = readMesh(at("v.off"));
  const auto r = runConformesh("view " + at("v.off") + " --vtu " + at("v.vtu") + " --json");
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(r.out)["vtu"] == at("v.vtu"));
  const std::string vtu = slurp(at("v.vtu"));
  CHECK(vtu.find("<VTKFile type=\"UnstructuredGrid\"") != std::string::npos);
  CHECK(vtu.find("NumberOfPoints=\"" + std::to_string(m.positions.size()) + "\" NumberOfCells=\"" +
                 std::to_string(m.faces.size()) + "\"") != std::string::npos);
}

TEST_CASE("repair --merge-tolerance: vertices 1e-6 apart merge at 1e-5 of the diagonal, not at the default 1e-10") {
  // Two triangles that should share the edge (1,0,0)–(0,1,0): one copy of (0,1,0) is exact, the copy of (1,0,0) is
  // 1e-6 off, i.e. 7e-7 of the bounding-box diagonal √2.
  {
    std::ofstream f(at("dup.off"));
    f << "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 1e-6\n0 1 0\n1 1 0\n3 0 1 2\n3 3 5 4\n";
  }
  auto run = [&](const std::string& extra, const std::string& out) {
    const auto r = runConformesh("repair " + at("dup.off") + " -o " + at(out) + " --json " + extra);
    REQUIRE(r.status == 0);
    return nlohmann::json::parse(r.out);
  };
  const auto loose = run("--merge-tolerance 1e-5", "loose.off"), strict = run("", "strict.off");
  CHECK(loose["merge_distance"].get<double>() == Approx(1e-5 * std::sqrt(2.0)).epsilon(1e-9));
  CHECK(strict["merge_distance"].get<double>() == Approx(1e-10 * std::sqrt(2.0)).epsilon(1e-9));
  CHECK(strict["merged_vertices"]["count"] == 1);  // only the exact duplicate
  CHECK(loose["merged_vertices"]["count"] == 2);
  const auto used = [](const MeshData& m) {
    std::set<int> v;
    for (const auto& f : m.faces) v.insert(f.begin(), f.end());
    return v.size();
  };
  // Strict: the triangles then share only vertex 2, a pinch that repair cuts again — two separate triangles.
  CHECK(used(readMesh(at("strict.off"))) == 6);
  CHECK(used(readMesh(at("loose.off"))) == 4);  // one square of two triangles
}

TEST_CASE("layout --pixels sets the picture's size") {
  REQUIRE(runConformesh("generate disk -o " + at("p.off")).status == 0);
  for (int px : {300, 900}) {
    const std::string svg = at("p" + std::to_string(px) + ".svg");
    REQUIRE(runConformesh("layout " + at("p.off") + " -o " + svg + (px == 900 ? "" : " --pixels 300")).status == 0);
    const std::string s = std::to_string(px);
    CHECK(slurp(svg).find("width=\"" + s + "\" height=\"" + s + "\" viewBox=\"0 0 " + s + " " + s + "\"") !=
          std::string::npos);
  }
  CHECK(runConformesh("layout " + at("p.off") + " -o " + at("q.svg") + " --pixels 10").status == 2);  // 64..8000
}

TEST_CASE("discretize --chart-lengths: chart-curve lengths, never shorter than the exact geodesic lengths") {
  // The ellipsoid's default lengths are GeographicLib geodesic distances; --chart-lengths integrates the metric along
  // the chart-straight segment, another curve between the same points: never shorter (a geodesic is shortest), and
  // longer where that segment is not a geodesic (the same connectivity and points in both files).
  const std::string args = "discretize ellipsoid --param f=0.3 -r 4 -o ";
  REQUIRE(runConformesh(args + at("geo.ply")).status == 0);
  REQUIRE(runConformesh(args + at("chart.ply") + " --chart-lengths").status == 0);
  const MeshData geoData = readMesh(at("geo.ply")), chartData = readMesh(at("chart.ply"));
  REQUIRE(geoData.faces == chartData.faces);
  const IntrinsicTriangulation geo = toTriangulation(geoData), chart = toTriangulation(chartData);
  double shortfall = 0, excess = 0;
  for (int h = 0; h < geo.mesh.nHalfedges(); ++h) {
    shortfall = std::max(shortfall, (geo.length(h) - chart.length(h)) / geo.length(h));
    excess = std::max(excess, (chart.length(h) - geo.length(h)) / geo.length(h));
  }
  INFO("relative: max shortfall " << shortfall << ", max excess " << excess);
  CHECK(shortfall < 1e-9);  // the quadrature's and GeographicLib's tolerances (docs/metrics.md), well above round-off
  CHECK(excess > 1e-6);
}

TEST_CASE("repair --area-tolerance: a sliver of area/longest² ≈ 9e-5 is kept at the default 1e-12, dropped at 1e-3") {
  // Face (0,0,0), (1,1,0), (2,2,1e-3): area |(1,1,0) × (2,2,1e-3)|/2 = 1e-3/√2, longest side² 8: ratio 8.8e-5.
  {
    std::ofstream f(at("sliver.off"));
    f << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 1e-3\n3 0 1 2\n3 1 3 2\n3 0 3 4\n";
  }
  for (bool dropped : {false, true}) {
    INFO((dropped ? "--area-tolerance 1e-3" : "default --area-tolerance (1e-12)"));
    const auto r = runConformesh("repair " + at("sliver.off") + " -o " + at("sliver-out.off") + " --json" +
                                 (dropped ? " --area-tolerance 1e-3" : ""));
    REQUIRE(r.status == 0);
    CHECK(nlohmann::json::parse(r.out)["degenerate_faces"]["count"] == (dropped ? 1 : 0));
    CHECK(readMesh(at("sliver-out.off")).faces.size() == (dropped ? 2u : 3u));
  }
}

TEST_CASE("generate genus --cell scales the surface: area × cell², shortest edge cell / resolution") {
  auto info = [&](const std::string& extra, const std::string& name) {
    REQUIRE(runConformesh("generate genus " + extra + " -o " + at(name)).status == 0);
    const auto r = runConformesh("info " + at(name) + " --json");
    REQUIRE(r.status == 0);
    return nlohmann::json::parse(r.out);
  };
  const auto one = info("", "g1.off"), two = info("--cell 2.5", "g2.off");
  CHECK(two["total_area"].get<double>() == Approx(6.25 * one["total_area"].get<double>()).epsilon(1e-12));
  CHECK(one["min_edge_length"].get<double>() == Approx(1.0 / 8).epsilon(1e-12));  // default resolution 8
  CHECK(two["min_edge_length"].get<double>() == Approx(2.5 / 8).epsilon(1e-12));
  CHECK(two["genus"] == 2);
}
