// test_qlm_grid.cpp — QuasiLocalMeasures-layout HDF5 files (qlm_grid.h), written here with the HDF5 C API from Smarr's
// closed-form Kerr horizon metric, read back: the samples at the nodes exactly, between the nodes at SampledMetric's
// fourth order, the area 8πMr₊ within the interpolation error; malformed files give InputErrors naming file, dataset
// and node.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/qlm_grid.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"
#include "support/scratch_dir.h"

using namespace conformesh::intrinsic;
using conformesh::InputError;
using conformesh::testing::scratchDir;

namespace {

const double M = 1, A = 0.8, RP = M + std::sqrt(M * M - A * A);

// Smarr's horizon 2-metric in Boyer–Lindquist θ, φ: q_θθ = ρ², q_φφ = (r₊²+a²)² sin²θ/ρ², q_θφ = 0.
double qtt(double t, double) { return RP * RP + A * A * std::cos(t) * std::cos(t); }
double qpp(double t, double p) { return std::pow(RP * RP + A * A, 2) * std::sin(t) * std::sin(t) / qtt(t, p); }
double qtp(double, double) { return 0; }

struct Layout {
  int ntheta, nphi, ng = 2, pad = 3;  // pad: maxntheta − ntheta = maxnphi − nphi
  bool writeScalars = true;
  std::function<void(std::vector<double>&, const char*)> spoil = [](std::vector<double>&, const char*) {};
  std::vector<const char*> components = {"qlm_qtt", "qlm_qtp", "qlm_qpp"};
};

void writeDataset(hid_t file, const std::string& name, const std::vector<hsize_t>& dims, const double* data) {
  const hid_t space = dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t set = H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(set), H5Sclose(space);
}

// Writes the file as CarpetIOHDF5 names QuasiLocalMeasures' arrays, nodes as SphericalSurface places them.
std::string writeQlm(const std::string& leaf, const Layout& l) {
  const std::string path = (scratchDir() / leaf).string();
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const int mt = l.ntheta + l.pad, mp = l.nphi + l.pad;
  const double dt = M_PI / (l.ntheta - 2 * l.ng), dp = 2 * M_PI / (l.nphi - 2 * l.ng);
  for (const char* c : l.components) {
    std::vector<double> v(size_t(mt) * mp, 0.0);
    auto f = std::string(c) == "qlm_qtt" ? qtt : std::string(c) == "qlm_qpp" ? qpp : qtp;
    for (int j = 0; j < l.nphi; ++j)
      for (int i = 0; i < l.ntheta; ++i) v[size_t(j) * mt + i] = f((i - l.ng + 0.5) * dt, (j - l.ng) * dp);
    l.spoil(v, c);
    writeDataset(file, std::string("QUASILOCALMEASURES::") + c + "[0] it=128 tl=0", {hsize_t(mp), hsize_t(mt)},
                 v.data());
  }
  if (l.writeScalars) {
    const std::pair<const char*, double> s[] = {
        {"qlm_ntheta", l.ntheta}, {"qlm_nphi", l.nphi}, {"qlm_nghoststheta", l.ng}, {"qlm_nghostsphi", l.ng}};
    for (auto& [n, x] : s) writeDataset(file, std::string("QUASILOCALMEASURES::") + n + "[0] it=128 tl=0", {}, &x);
  }
  H5Fclose(file);
  return path;
}

std::string errorOf(const std::string& path, const QlmGridOptions& o = {}) {
  try {
    readQlmGridHdf5(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("QLM grid: Kerr horizon reads back at the nodes, converts (θ,φ) to (u,v) = (φ,θ)", "[qlm]") {
  const std::string path = writeQlm("kerr.h5", {24 + 4, 48 + 4});
  REQUIRE(hasQlmTwoMetric(path));
  const SampledField f = readQlmGridHdf5(path);
  REQUIRE(f.nu == 48);
  REQUIRE(f.nv == 24);
  REQUIRE(f.domain.poleAtV0);
  REQUIRE(f.domain.poleAtV1);
  // At the nodes the numbers are those written. Tolerance 1e-13 relative: the writer places node i at (i−2+½)·Δθ, the
  // field at (j+½)π/NV; the two positions differ by an ulp, and so do the closed forms evaluated there.
  for (int j = 0; j < f.nv; ++j)
    for (int i = 0; i < f.nu; ++i) {
      const double t = f.nodeV(j), p = f.nodeU(i);
      const size_t k = size_t(j) * f.nu + i;
      REQUIRE(f.guu[k] == Approx(qpp(t, p)).epsilon(1e-13));
      REQUIRE(f.gvv[k] == Approx(qtt(t, p)).epsilon(1e-13));
      REQUIRE(f.guv[k] == 0);
    }
}

TEST_CASE("QLM grid: readSampledField (every --field) recognises the QuasiLocalMeasures layout", "[qlm]") {
  const SampledField f = readSampledField(writeQlm("dispatch.h5", {12 + 4, 24 + 4}));
  CHECK(f.nu == 24);
  CHECK(f.nv == 12);
  CHECK(f.gvv[0] == Approx(qtt(M_PI / 24, 0)).epsilon(1e-13));  // g_vv = q_θθ at the first interior node
}

TEST_CASE("QLM grid: between nodes at fourth order; area 8πMr₊ within the interpolation error", "[qlm]") {
  double err[2], areaErr[2];
  const int nvs[2] = {16, 32};
  for (int r = 0; r < 2; ++r) {
    const int nv = nvs[r];
    const SampledMetric m(readQlmGridHdf5(writeQlm("kerr" + std::to_string(nv) + ".h5", {nv + 4, 2 * nv + 4})));
    err[r] = 0;
    const double h = M_PI / nv;
    for (int j = 1; j + 1 < nv; ++j)  // cell midpoints away from the pole rows
      for (int i = 0; i < 2 * nv; ++i) {
        const double t = (j + 1.0) * h, p = (i + 0.5) * h;
        const Eigen::Matrix2d g = m.g(p, t);
        err[r] = std::max({err[r], std::abs(g(0, 0) - qpp(t, p)), std::abs(g(1, 1) - qtt(t, p)), std::abs(g(0, 1))});
      }
    areaErr[r] = std::abs(metricArea(m).value - 8 * M_PI * M * RP) / (8 * M_PI * M * RP);
  }
  const double order = std::log2(err[0] / err[1]);
  INFO("midpoint errors " << err[0] << " " << err[1] << " order " << order << "; area errors " << areaErr[0] << " "
                          << areaErr[1]);
  CHECK(order > 3.5);  // SampledMetric is fourth order in g (sampled_metric.h); 3.5 allows pre-asymptotic slack
  CHECK(areaErr[1] < 1e-6);  // measured 2e-8 at NV = 32; the midpoint error in g there is 3.5e-6
  CHECK(areaErr[1] < areaErr[0]);
}

TEST_CASE("QLM grid: malformed files name file, dataset and node", "[qlm]") {
  SECTION("missing component") {
    Layout l{20, 36};
    l.components = {"qlm_qtt", "qlm_qpp"};
    const std::string e = errorOf(writeQlm("missing.h5", l));
    CHECK_THAT(e, Catch::Contains("missing.h5") && Catch::Contains("qlm_qtp[0]"));
  }
  SECTION("wrong grid size") {
    Layout l{20, 36};
    l.pad = 0;
    const std::string path = writeQlm("small.h5", l);
    QlmGridOptions o;
    o.ntheta = 30;  // disagrees with the file's qlm_ntheta
    CHECK_THAT(errorOf(path, o), Catch::Contains("small.h5") && Catch::Contains("qlm_ntheta is 20"));
    Layout n{20, 36};
    n.pad = 0, n.writeScalars = false;
    const std::string p2 = writeQlm("noscalars.h5", n);
    o = {};
    o.ntheta = 24, o.nphi = 36, o.nghoststheta = 2, o.nghostsphi = 2;
    CHECK_THAT(errorOf(p2, o), Catch::Contains("noscalars.h5") && Catch::Contains("has shape (36 x 20)"));
    CHECK_THAT(errorOf(p2), Catch::Contains("give qlm_ntheta"));
  }
  SECTION("NaN") {
    Layout l{20, 36};
    l.spoil = [&](std::vector<double>& v, const char* c) {
      if (std::string(c) == "qlm_qtp") v[size_t(7) * (20 + 3) + 5] = NAN;  // θ index 5, φ index 7
    };
    const std::string e = errorOf(writeQlm("nan.h5", l));
    CHECK_THAT(e, Catch::Contains("nan.h5") && Catch::Contains("qlm_qtp[0] it=128") &&
                      Catch::Contains("theta index 5, phi index 7"));
    CHECK_THAT(e, Catch::Contains("theta 0.687223") && Catch::Contains("phi 0.981748"));  // (5−2+½)π/16, (7−2)·2π/32
  }
  SECTION("not positive definite") {
    Layout l{20, 36};
    l.spoil = [&](std::vector<double>& v, const char* c) {
      if (std::string(c) == "qlm_qtp") v[size_t(10) * (20 + 3) + 9] = 100;  // |q_θφ| > √(q_θθ q_φφ)
    };
    const std::string e = errorOf(writeQlm("indef.h5", l));
    CHECK_THAT(e, Catch::Contains("indef.h5") && Catch::Contains("not positive definite") &&
                      Catch::Contains("theta index 9, phi index 10"));
  }
}
