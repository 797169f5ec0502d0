// End-to-end tests of the smooth reference in `conformesh remesh FAMILY` reports (issue #23 item 2): the mesh's total
// area and ∫K dA beside the metric's quadratures, against closed forms — the sphere's 4πR² and 4π, the Kerr horizon's
// Smarr area 8πMr₊, ∫K dA = 2πχ = 4π on every genus-0 surface, 0 on the torus, 2π(1 − cos α) on a spherical cap — in
// --json (smooth_reference) and in the text report.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

using conformesh::testing::runConformesh;

namespace {
nlohmann::json remeshJson(const std::string& args) {
  const auto out = (conformesh::testing::scratchDir() / "report.ply").string();
  const auto r = runConformesh("-q remesh " + args + " --no-check --json -o " + out);
  INFO("conformesh remesh " << args << "\n" << r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out).at("smooth_reference");
}
// Quadrature tolerances (smooth_reference.h): area relative 1e-12, ∫K dA absolute 1e-10; 1e-9 leaves room for the
// adaptive rule's estimate being an estimate. The mesh's deficits total 2πχ to round-off (Gauss–Bonnet residual ~1e-12).
constexpr double kQuadrature = 1e-9;
}  // namespace

TEST_CASE("remesh report: sphere of radius 2, area 16 pi and integral K dA 4 pi") {
  const double eps = 0.1, radius = 2;
  const auto s = remeshJson("sphere --param R=2 --eps 0.1");
  CHECK(s.at("smooth_area").get<double>() == Approx(16 * M_PI).epsilon(kQuadrature));
  CHECK(s.at("smooth_total_curvature").get<double>() == Approx(4 * M_PI).margin(kQuadrature));
  CHECK(s.at("mesh_total_curvature").get<double>() == Approx(4 * M_PI).margin(kQuadrature));
  CHECK(s.at("gauss_bonnet").get<double>() == Approx(4 * M_PI).margin(1e-15));
  CHECK(s.at("total_curvature_relative_difference").get<double>() == Approx(0).margin(kQuadrature));
  // Flat triangles with geodesic side lengths are smaller than the spherical ones (K > 0), by O(ε²/R²).
  const double rel = s.at("area_relative_difference").get<double>();
  CHECK(rel < 0);
  CHECK(rel > -eps * eps / (radius * radius));
  CHECK(rel == Approx(s.at("mesh_area").get<double>() / (16 * M_PI) - 1).margin(1e-9));
}

TEST_CASE("remesh report: Kerr a/M = 0.99 has Smarr's area 8 pi M r+ and integral K dA 4 pi") {
  const auto s = remeshJson("kerr-newman --param a=0.99 --eps 0.1");
  const double rp = 1 + std::sqrt(1 - 0.99 * 0.99);
  CHECK(s.at("smooth_area").get<double>() == Approx(8 * M_PI * rp).epsilon(kQuadrature));
  CHECK(s.at("smooth_total_curvature").get<double>() == Approx(4 * M_PI).margin(kQuadrature));
  CHECK(s.at("mesh_total_curvature").get<double>() == Approx(4 * M_PI).margin(kQuadrature));
  CHECK(std::abs(s.at("area_relative_difference").get<double>()) < 0.1 * 0.1);  // O(ε²), ε = 0.1 (M = 1)
}

TEST_CASE("remesh report: the torus's integral K dA vanishes, so its relative difference is null") {
  const auto s = remeshJson("torus --eps 0.5");
  CHECK(s.at("smooth_total_curvature").get<double>() == Approx(0).margin(kQuadrature));
  CHECK(s.at("gauss_bonnet").get<double>() == Approx(0).margin(1e-15));
  CHECK(s.at("total_curvature_relative_difference").is_null());
  CHECK(s.at("smooth_area").get<double>() == Approx(4 * M_PI * M_PI * 3).epsilon(kQuadrature));
}

TEST_CASE("remesh report: a spherical cap's interior deficits fall short of 2 pi (1 - cos alpha) by O(eps)") {
  const double eps = 0.04;
  const auto s = remeshJson("spherical-cap --eps 0.04");
  CHECK(s.at("gauss_bonnet").is_null());
  CHECK(s.at("smooth_total_curvature").get<double>() == Approx(2 * M_PI * (1 - std::cos(1.0))).margin(kQuadrature));
  // The deficits leave out the boundary strip, of width below the circumradius bound ε along the boundary of length
  // 2π sin α, where K = 1: at most K · length · ε.
  const double diff = s.at("total_curvature_difference").get<double>();
  CHECK(diff < 0);
  CHECK(diff > -2 * M_PI * std::sin(1.0) * eps);
}

TEST_CASE("remesh report: the text shows the area, integral K dA and what the within share means") {
  const auto out = (conformesh::testing::scratchDir() / "report_text.ply").string();
  const auto r = runConformesh("-q remesh sphere --param R=2 --eps 0.1 -o " + out);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("total area") != std::string::npos);
  CHECK(r.out.find("(smooth 50.26548246,") != std::string::npos);  // 16π to ten digits
  CHECK(r.out.find("2 pi chi 12.56637061") != std::string::npos);  // 4π
  // r = 0.05 √(16π) = 0.3545 = 3.5 ε.
  CHECK(r.out.find("balls of radius r = 3.5 eps") != std::string::npos);
}

TEST_CASE("remesh --horizon report: smooth_reference's area is the horizon's (8 pi M r+ for Kerr-Schild a = 0.8)") {
  const std::string shape = std::string(CONFORMESH_SOURCE_DIR) + "/docs/examples/kerr-schild-a0.8.json";
  const auto s = remeshJson("--horizon " + shape + " --param a=0.8 --eps 0.2");
  CHECK(s.at("smooth_area").get<double>() == Approx(8 * M_PI * 1.6).epsilon(kQuadrature));
  CHECK(s.at("smooth_total_curvature").get<double>() == Approx(4 * M_PI).margin(1e-8));
}

TEST_CASE("remesh --vtk: a surface with no embedding says in its title that it is drawn on the reference surface") {
  const auto dir = conformesh::testing::scratchDir();
  for (const auto& [args, embedded] : {std::pair<std::string, bool>{"kerr-newman --param a=0.99 --eps 0.2", false},
                                       {"ellipsoid --param f=0.3 --eps 0.2", true}}) {
    const auto vtk = (dir / "title.vtk").string();
    const auto r = runConformesh("-q remesh " + args + " --no-check -o " + (dir / "title.ply").string() + " --vtk " + vtk);
    INFO(args << "\n" << r.err);
    REQUIRE(r.status == 0);
    std::ifstream in(vtk);
    std::string header, title;
    std::getline(in, header);
    std::getline(in, title);
    // Kerr a/M > √3/2 has negative curvature at the poles: no embedding (Smarr 1973); the ellipsoid is its embedding.
    CHECK((title.find("no embedding in R3") == std::string::npos) == embedded);
  }
}
