// End-to-end tests of `conformesh remesh --horizon SHAPE.json --spatial-metric ...`: the Kerr horizon of Kerr–Schild
// coordinates (docs/examples/kerr-schild-a0.8.json, fitted at l_max = 16) reports Smarr's area 8πMr₊, the irreducible
// mass √(Mr₊/2), the equatorial circumference 4πM and the spin 0.8; bad input exits 1 with the file named.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"

namespace fs = std::filesystem;
using conformesh::testing::runConformesh;

namespace {
const std::string kShape = std::string(CONFORMESH_SOURCE_DIR) + "/docs/examples/kerr-schild-a0.8.json";
}

TEST_CASE("remesh --horizon: the Kerr-Schild horizon a = 0.8 reports Smarr's geometry and its spin") {
  const fs::path out = conformesh::testing::scratchDir() / "horizon.ply";
  const auto r = runConformesh("-q remesh --horizon " + kShape +
                               " --spatial-metric kerr-schild --param M=1 --param a=0.8 --eps 0.15 --no-check --json "
                               "-o " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& h = j.at("horizon");
  const double rp = 1.6;
  // Smooth-metric figures at l_max = 16: the fit's error is ~1e-14 in the area (test_horizon_surface), the curve
  // quadratures are spectral; 1e-9 leaves room for both.
  CHECK(h.at("area").get<double>() == Approx(8 * M_PI * rp).epsilon(1e-9));
  CHECK(h.at("irreducible_mass").get<double>() == Approx(std::sqrt(rp / 2)).epsilon(1e-9));
  CHECK(h.at("equatorial_circumference").get<double>() == Approx(4 * M_PI).epsilon(1e-9));
  CHECK(h.at("spin").get<double>() == Approx(0.8).margin(1e-6));
  CHECK(h.at("polar_circumference").get<double>() < h.at("equatorial_circumference").get<double>());
  // The mesh area: chords for arcs, O(ε²) ≈ 1 % at ε = 0.15.
  CHECK(h.at("mesh_area").get<double>() == Approx(8 * M_PI * rp).epsilon(0.01));
  CHECK(fs::exists(out));
}

TEST_CASE("remesh --horizon: bad input exits 1 (InputError) and names the file") {
  const fs::path dir = conformesh::testing::scratchDir(), bad = dir / "bad_shape.json";
  std::ofstream(bad) << R"({"center": [0, 0, 0], "coefficients": [[0, 0, 6.1], [2, 3, 0.1]]})";
  auto r = runConformesh("-q remesh --horizon " + bad.string() + " --eps 0.2 -o " + (dir / "x.ply").string());
  CHECK(r.status == 1);  // kExitFailure: main.cpp maps every InputError to 1 (2 is CLI usage)
  CHECK(r.err.find("bad_shape.json") != std::string::npos);
  CHECK(r.err.find("|m| <= l") != std::string::npos);
  r = runConformesh("-q remesh --horizon " + kShape + " --spatial-metric kerr --eps 0.2 -o " +
                    (dir / "x.ply").string());
  CHECK(r.status == 1);  // kExitFailure: main.cpp maps every InputError to 1 (2 is CLI usage)
  CHECK(r.err.find("unknown spatial metric 'kerr'") != std::string::npos);
  r = runConformesh("-q remesh sphere --horizon " + kShape + " --eps 0.2 -o " + (dir / "x.ply").string());
  CHECK(r.status == 1);  // kExitFailure: main.cpp maps every InputError to 1 (2 is CLI usage)
  CHECK(r.err.find("--horizon replaces the FAMILY") != std::string::npos);
}

// docs/horizons.md §5b: the same shape in a Kerr–Schild γ sampled on a 40³ grid (h = 0.138) written as HDF5 in the
// ADMBase layout, read by `--spatial-metric FILE.h5:/group`.
TEST_CASE("remesh --horizon in a sampled gamma (HDF5): Smarr's area, spin and Gauss-Bonnet") {
  using namespace conformesh::intrinsic;
  const fs::path dir = conformesh::testing::scratchDir(), grid = dir / "ks08.h5", out = dir / "sampled.ply";
  const int n = 40;
  const double L = 2.7, h = 2 * L / (n - 1);
  writeSpatialMetricHdf5(sampleSpatialMetric(KerrSchildMetric(1.0, 0.8, Eigen::Vector3d::Zero()), {n, n, n},
                                             Eigen::Vector3d::Constant(-L), Eigen::Vector3d::Constant(h)),
                         grid.string(), "/it0");
  const auto r = runConformesh("-q remesh --horizon " + kShape + " --spatial-metric " + grid.string() +
                               ":/it0 --eps 0.15 --json -o " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& hz = j.at("horizon");
  // test_sampled_spatial_metric measures the area error of this grid at ~1e-8 and the spin's at ~1e-6.
  CHECK(hz.at("area").get<double>() == Approx(8 * M_PI * 1.6).epsilon(1e-6));
  CHECK(hz.at("spin").get<double>() == Approx(0.8).margin(1e-4));
  CHECK(std::abs(j.at("quality").at("gauss_bonnet_residual").get<double>()) < 1e-9);
}

// docs/horizons.md §5c: a time series of 10 horizons — the Kerr–Schild spheroid with the spin rising from a = 0.50
// to 0.86 (a slowly spinning-up black hole), each a shape file naming its spatial metric, parameters and time — run
// by one `conformesh sweep`, whose table has one row per time with the horizon's area, irreducible mass and spin.
TEST_CASE("sweep over horizon files: a time series with area, irreducible mass and spin per time") {
  using namespace conformesh::intrinsic;
  const fs::path dir = conformesh::testing::scratchDir() / "series", out = dir / "out";
  fs::create_directories(dir / "h");
  const int steps = 10;
  for (int t = 0; t < steps; ++t) {
    const double a = 0.5 + 0.04 * t, rp = 1 + std::sqrt(1 - a * a);
    const Strahlkorper s = fitStrahlkorper(
        [&](double th, double) {
          return 1 / std::sqrt(std::pow(std::sin(th), 2) / (rp * rp + a * a) + std::pow(std::cos(th), 2) / (rp * rp));
        },
        16, Eigen::Vector3d::Zero());
    nlohmann::json j = nlohmann::json::parse(strahlkorperToJson(s));
    j["spatial_metric"] = "kerr-schild";
    j["params"] = {{"M", 1.0}, {"a", a}};
    j["time"] = 10.0 * t;
    char name[32];
    std::snprintf(name, sizeof name, "t%03d.json", 10 * t);
    std::ofstream(dir / "h" / name) << j.dump();
  }
  std::ofstream(dir / "series.json")
      << R"({"studies": [{"name": "AhA", "input": "h/*.json", "eps": 0.35, "options": {"no-check": true}}]})";
  const auto r = runConformesh("-q sweep " + (dir / "series.json").string() + " -o " + out.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json table = nlohmann::json::parse(conformesh::testing::slurp(out / "table.json"));
  REQUIRE(table.size() == static_cast<size_t>(steps));
  for (int t = 0; t < steps; ++t) {
    const nlohmann::json& row = table[t];
    const double a = 0.5 + 0.04 * t, rp = 1 + std::sqrt(1 - a * a);
    INFO("row " << t);
    REQUIRE(row.at("status") == "ok");
    CHECK(row.at("time").get<double>() == 10.0 * t);
    // Analytic γ, l_max = 16: the area to the quadrature's 1e-10, the spin by the spectral curve lengths.
    CHECK(row.at("horizon").at("area").get<double>() == Approx(8 * M_PI * rp).epsilon(1e-9));
    CHECK(row.at("horizon").at("irreducible_mass").get<double>() == Approx(std::sqrt(rp / 2)).epsilon(1e-9));
    CHECK(row.at("horizon").at("spin").get<double>() == Approx(a).margin(1e-6));
    CHECK(std::abs(row.at("quality").at("gauss_bonnet_residual").get<double>()) < 1e-9);
  }
  const std::string csv = conformesh::testing::slurp(out / "table.csv");
  CHECK(csv.find(",time,horizon_area,irreducible_mass,equatorial_circumference,polar_circumference,spin\n") !=
        std::string::npos);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == steps + 1);
}
