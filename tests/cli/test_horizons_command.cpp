// End-to-end tests of `conformesh horizons SERIES -o DIR` (docs/horizons.md §5c) on the Kerr–Schild test series of
// `conformesh generate horizon-series`: ten horizons r = r₊ with the spin rising a = 0.5 … 0.9, plus a broken file in
// the middle. Every ok row must reproduce Kerr (Smarr): area 8πMr₊, M_irr = √(Mr₊/2), C_eq = 4πM, spin a; the
// broken step gets its row with its error and exit status 1; series.csv and series.json agree to the last digit; a
// rerun keeps every step; the time comes from the file name when the file has none; a missing SERIES exits 2.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/metric/strahlkorper_io.h"

namespace fs = std::filesystem;
using conformesh::testing::runConformesh;
using nlohmann::json;

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {  // fields with quotes ("" inside), as the table writes
  std::vector<std::string> out(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

// Kerr's r₊ for M = 1.
double rPlus(double a) { return 1 + std::sqrt(1 - a * a); }

}  // namespace

TEST_CASE("horizons: ten Kerr-Schild horizons and a broken file in one command") {
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_series", shapes = dir / "h", out = dir / "out";
  fs::remove_all(dir);
  auto g = runConformesh("-q generate horizon-series -o " + shapes.string() + " --steps 10 --a0 0.5 --a1 0.9 --dt 10");
  REQUIRE(g.status == 0);
  std::ofstream(shapes / "t045.00.json") << "{\"center\": [0, 0, 0], \"coefficients\": [[0, 0\n";  // truncated JSON
  const auto r = runConformesh("-q horizons " + shapes.string() + " -o " + out.string() + " --eps 0.35 --no-plot --json");
  INFO(r.err);
  CHECK(r.status == 1);  // a failed step: the table is written, the exit status says so (docs/cli.md#horizons)
  const json report = json::parse(r.out);
  const json& rows = report.at("rows");
  REQUIRE(rows.size() == 11);
  int ok = 0;
  double previous = -1;
  for (const json& row : rows) {
    const double t = row.at("time").get<double>();
    CHECK(t > previous);  // ordered by time
    previous = t;
    if (row.at("file") == "t045.00.json") {
      CHECK(row.at("status") == "failed");
      CHECK(row.at("time_source") == "name");  // the file does not parse: its time is its name's
      CHECK(row.at("error").get<std::string>().find("t045.00.json: not valid JSON") != std::string::npos);
      CHECK(row.at("area").is_null());
      continue;
    }
    ++ok;
    REQUIRE(row.at("status") == "ok");
    CHECK(row.at("time_source") == "file");
    const double a = 0.5 + 0.4 * t / 90, rp = rPlus(a);
    // Smooth-metric figures of shapes fitted at l_max = 16: the fit's area error is ~1e-14 (test_horizon_surface),
    // the circumference quadratures spectral; 1e-9 relative (area, M_irr, C_eq) and 1e-6 absolute (spin, through the
    // inverted elliptic-integral ratio) are the tolerances of `remesh --horizon` (test_horizon_command).
    CHECK(row.at("area").get<double>() == Approx(8 * M_PI * rp).epsilon(1e-9));
    CHECK(row.at("irreducible_mass").get<double>() == Approx(std::sqrt(rp / 2)).epsilon(1e-9));
    CHECK(row.at("equatorial_circumference").get<double>() == Approx(4 * M_PI).epsilon(1e-9));
    CHECK(row.at("spin").get<double>() == Approx(a).margin(1e-6));
    // Gauss–Bonnet of the intrinsic triangulation holds to round-off: ∫K dA = 4π.
    CHECK(std::abs(row.at("gauss_bonnet_residual").get<double>()) < 1e-9);
    CHECK(row.at("total_curvature").get<double>() == Approx(4 * M_PI).epsilon(1e-9));
    // ∫K dA of the smooth metric: adaptive quadrature of Brioschi's K on differenced second derivatives, ~1e-6
    // (docs/horizons.md §1: 1e-4 at worst for the analytic Kerr–Schild K near the poles).
    CHECK(row.at("smooth_total_curvature").get<double>() == Approx(4 * M_PI).epsilon(1e-4));
    CHECK(row.at("min_angle_deg").get<double>() > 20.7);  // the refinement's angle bound (ratio √2)
    CHECK(row.at("e_G").get<double>() > 0);
  }
  CHECK(ok == 10);

  // series.json holds the same rows; series.csv the same values, each a %.17g round trip of the JSON's double.
  std::ifstream js(out / "series.json");
  const json file = json::parse(js);
  CHECK(file.at("rows") == rows);
  CHECK(file.at("run").at("failed") == 1);
  std::ifstream csv(out / "series.csv");
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = splitCsvLine(line);
  size_t k = 0;
  for (; std::getline(csv, line); ++k) {
    REQUIRE(k < rows.size());
    const std::vector<std::string> fields = splitCsvLine(line);
    REQUIRE(fields.size() == header.size());
    for (size_t i = 0; i < header.size(); ++i) {
      const json& v = rows[k].at(header[i]);
      INFO(header[i] << " row " << k);
      if (v.is_null())
        CHECK(fields[i].empty());
      else if (v.is_number())
        CHECK(std::stod(fields[i]) == v.get<double>());
      else if (v.is_string())
        CHECK(fields[i] == v.get<std::string>());
    }
  }
  CHECK(k == rows.size());

  // A rerun with the same SERIES and DIR keeps every step (failed ones too, without --retry-failed).
  const auto again = runConformesh("-q horizons " + shapes.string() + " -o " + out.string() + " --eps 0.35 --no-plot --json");
  CHECK(again.status == 1);
  const json second = json::parse(again.out);
  CHECK(second.at("run").at("ran") == 0);
  CHECK(second.at("run").at("skipped") == 11);
  CHECK(second.at("rows") == rows);

  // A step added to the folder (a running simulation): only it is computed, the other records are kept.
  REQUIRE(runConformesh("-q generate horizon-series -o " + (dir / "more").string() + " --steps 1 --a0 0.7 --a1 0.7")
              .status == 0);
  fs::copy_file(dir / "more" / "t000.00.json", shapes / "t095.00.json");  // its "time" key says 0: listed first
  const auto grown = runConformesh("-q horizons " + shapes.string() + " -o " + out.string() + " --eps 0.35 --no-plot --json");
  const json third = json::parse(grown.out);
  CHECK(third.at("run").at("ran") == 1);
  CHECK(third.at("run").at("skipped") == 11);
  CHECK(third.at("rows").size() == 12);
}

TEST_CASE("horizons: --spatial-metric and --param for every step, the time from the file name") {
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_override", shapes = dir / "h";
  fs::remove_all(dir);
  REQUIRE(runConformesh("-q generate horizon-series -o " + (dir / "g").string() + " --steps 1 --a0 0.6 --a1 0.6")
              .status == 0);
  std::ifstream in(dir / "g" / "t000.00.json");
  json shape = json::parse(in);
  shape.erase("time");
  shape["params"] = {{"M", 1}, {"a", 0.3}};  // wrong on purpose: --param a=0.6 replaces it
  fs::create_directories(shapes);
  std::ofstream(shapes / "AhA_it0025.json") << shape.dump();
  const auto r = runConformesh("-q horizons " + shapes.string() + " -o " + (dir / "out").string() +
                               " --spatial-metric kerr-schild --param a=0.6 --eps 0.4 --no-check --no-plot --json");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const json row = json::parse(r.out).at("rows").at(0);
  CHECK(row.at("time").get<double>() == 25);
  CHECK(row.at("time_source") == "name");
  CHECK(row.at("spin").get<double>() == Approx(0.6).margin(1e-6));
  CHECK(row.at("e_G").is_null());  // --no-check
}

TEST_CASE("horizons: a SERIES that is not a folder of shapes exits 2 and names it") {
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_bad";
  fs::remove_all(dir);
  fs::create_directories(dir / "empty");
  auto r = runConformesh("-q horizons " + (dir / "nothing").string() + " -o " + (dir / "out").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("nothing: expected a folder of horizon shape files") != std::string::npos);
  r = runConformesh("-q horizons " + (dir / "empty").string() + " -o " + (dir / "out").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("no horizon shape file") != std::string::npos);
  r = runConformesh("-q generate horizon-series -o " + (dir / "g").string() + " --a1 1.2");
  CHECK(r.status == 2);
  CHECK(r.err.find("|a| < M") != std::string::npos);
}

TEST_CASE("horizons: one HDF5 file with a group per step and a broken group") {
  using namespace conformesh::intrinsic;
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_hdf5", file = dir / "series.h5", out = dir / "out";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Ten Kerr–Schild horizons as coefficient groups (written from C++), and at t = 45 a sampled radius with r ≤ 0.
  std::vector<HorizonShapeGroup> groups;
  for (int k = 0; k < 10; ++k) {
    const double a = 0.5 + 0.4 * k / 9, rp = rPlus(a), R2 = rp * rp + a * a;
    HorizonShapeGroup g;
    char name[32];
    std::snprintf(name, sizeof name, "/t%03d", 10 * k);
    g.group = name;
    g.record.shape = fitStrahlkorper([&](double t, double) {
      return 1 / std::sqrt(std::sin(t) * std::sin(t) / R2 + std::cos(t) * std::cos(t) / (rp * rp));
    }, 16, Eigen::Vector3d::Zero());
    g.record.meta.params = {{"M", 1.0}, {"a", a}};
    g.record.meta.hasTime = true, g.record.meta.time = 10 * k;
    groups.push_back(g);
  }
  HorizonShapeGroup broken;
  broken.group = "/t045";
  broken.record.sampled = true;
  broken.record.meta.hasTime = true, broken.record.meta.time = 45;
  broken.samples.r = Eigen::MatrixXd::Constant(5, 10, 2.0);
  broken.samples.r(3, 7) = -1;
  groups.push_back(broken);
  writeHorizonShapesHdf5(file.string(), groups);

  const auto r = runConformesh("-q horizons " + file.string() + " -o " + out.string() + " --eps 0.35 --no-plot --json");
  INFO(r.err);
  CHECK(r.status == 1);
  const json rows = json::parse(r.out).at("rows");
  REQUIRE(rows.size() == 11);
  int ok = 0;
  for (const json& row : rows) {
    const double t = row.at("time").get<double>();
    if (row.at("file") == "series.h5:/t045") {
      CHECK(row.at("status") == "failed");
      CHECK(row.at("error_kind") == "input");
      CHECK_THAT(row.at("error").get<std::string>(),
                 Catch::Contains("series.h5:/t045: dataset 'radius'") && Catch::Contains("radius[3][7]"));
      continue;
    }
    ++ok;
    REQUIRE(row.at("status") == "ok");
    CHECK(row.at("time_source") == "file");
    const double a = 0.5 + 0.4 * t / 90, rp = rPlus(a);
    CHECK(row.at("area").get<double>() == Approx(8 * M_PI * rp).epsilon(1e-9));  // as the JSON series above
    CHECK(row.at("spin").get<double>() == Approx(a).margin(1e-6));
    CHECK(std::abs(row.at("gauss_bonnet_residual").get<double>()) < 1e-9);
    // The approximate Killing vector's spin on the ~640-vertex mesh of ε = 0.35: a discretization estimate
    // (docs/horizons.md §4d), measured within 1e-2 of a here; 3e-2 allows for other meshes of the same size.
    CHECK(row.at("spin_killing").get<double>() == Approx(a).margin(3e-2));
    const json record = json::parse(std::ifstream(out / "cases" / row.at("id").get<std::string>() / "record.json"));
    CHECK(record.at("horizon").at("shape").at("form") == "coefficients");
    CHECK(record.at("horizon").at("killing").at("degenerate") == false);
  }
  CHECK(ok == 10);
  // A rerun over the same file keeps every step; a group's id hashes its shape, not the whole file.
  const auto again = runConformesh("-q horizons " + file.string() + " -o " + out.string() + " --eps 0.35 --no-plot --json");
  CHECK(json::parse(again.out).at("run").at("skipped") == 11);
}

TEST_CASE("horizons: generate horizon-series --hdf5 --sampled, and remesh --horizon FILE.h5:/group") {
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_hdf5_generate", file = dir / "s.h5";
  fs::remove_all(dir);
  fs::create_directories(dir);
  REQUIRE(runConformesh("-q generate horizon-series --hdf5 " + file.string() + " --steps 2 --a0 0.6 --a1 0.9 --sampled")
              .status == 0);
  const auto r = runConformesh("remesh --horizon " + file.string() + ":/t010.00 --param a=0.9 --eps 0.3 --json -o " +
                               (dir / "o.ply").string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("sampled radius fitted at l_max = 16") != std::string::npos);  // the residual is reported
  const json h = json::parse(r.out).at("horizon");
  // The spheroid sampled on a 34 × 68 Gauss–Legendre grid and projected at l_max = 16 (exact quadrature) is the
  // l_max = 16 fit: Smarr's area to the fit's ~1e-12 (docs/horizons.md §3); 1e-9 as remesh --horizon.
  CHECK(h.at("area").get<double>() == Approx(8 * M_PI * rPlus(0.9)).epsilon(1e-9));
  CHECK(h.at("spin").get<double>() == Approx(0.9).margin(1e-6));
  const json& shape = h.at("shape");  // how the shape was given, with the fit's residual at the nodes
  CHECK(shape.at("form") == "sampled");
  CHECK(shape.at("l_max") == 16);
  CHECK(shape.at("theta_nodes") == "gauss-legendre");
  CHECK(shape.at("grid") == json::array({34, 68}));
  // The spheroid is not band-limited: the l_max = 16 projection misses it at the nodes by its l > 16 tail, measured
  // 2.4e-10 at a = 0.9; 1e-8 leaves room, a wrong projection would be O(0.1).
  CHECK(shape.at("max_residual").get<double>() < 1e-8);
  CHECK(shape.at("rms_residual").get<double>() <= shape.at("max_residual").get<double>());
  const auto bad = runConformesh("-q generate horizon-series --sampled -o " + (dir / "x").string());
  CHECK(bad.status == 2);
}

// --lmax sets the degree of the generator's Strahlkorper fit: the Kerr-Schild spheroid is even in cos(theta) and
// axisymmetric, so its coefficients are a_l0 with l even, and the fit at l_max = L carries degrees up to exactly L.
TEST_CASE("generate horizon-series --lmax: the fit's highest degree") {
  const fs::path dir = conformesh::testing::scratchDir() / "horizons_lmax";
  fs::remove_all(dir);
  for (int lMax : {4, 10}) {
    const fs::path out = dir / std::to_string(lMax);
    REQUIRE(runConformesh("-q generate horizon-series -o " + out.string() + " --steps 1 --a0 0.8 --a1 0.8 --lmax " +
                          std::to_string(lMax))
                .status == 0);
    std::ifstream in(out / "t000.00.json");
    const json shape = json::parse(in);
    int highest = -1;
    for (const auto& c : shape.at("coefficients")) {
      const int l = c.at(0).get<int>(), m = c.at(1).get<int>();
      CHECK(l <= lMax);
      if (c.at(2).get<double>() != 0.0 && m == 0) highest = std::max(highest, l);
    }
    CHECK(highest == lMax);
  }
}
