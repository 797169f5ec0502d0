// test_sampled_field_hdf5.cpp — sampled metric fields in HDF5: files written here with the HDF5 C API directly (not
// with conformesh's writer), in the layouts a physics code or h5py produces, read back bit for bit against the closed
// forms they were sampled from; the HDF5 and text readers give the same metric; conformesh's writer round-trips; and
// every kind of bad file is an InputError naming the file, group and dataset or attribute.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

#include "support/scratch_dir.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

// The test process's own scratch folder, removed at exit (CTest runs the test cases in parallel processes).
fs::path dir() { return conformesh::testing::scratchDir(); }

// What a test file holds; every member can be broken on purpose.
struct RawField {
  int nu = 0, nv = 0;
  std::vector<double> guu, guv, gvv;
  std::vector<double> chart = {0, 2 * M_PI, 0, 2 * M_PI};
  long long periodicU = 1, periodicV = 1;
  std::string poles;       // empty: no attribute
  bool h5pyStyle = false;  // periodic flags as h5py's bool enum, poles as a variable-length string
  bool float32 = false;    // datasets stored as IEEE float32
  std::string group = "/";
  std::vector<std::string> skip;           // attributes or datasets not written
  std::function<void(hid_t group)> extra;  // anything else, written into the group
};

bool skipped(const RawField& f, const std::string& name) {
  for (const std::string& s : f.skip)
    if (s == name) return true;
  return false;
}

// Writes `f` with the plain HDF5 C API, independently of conformesh's writer.
void writeRaw(const RawField& f, const fs::path& path) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(file >= 0);
  hid_t g = file;
  if (f.group != "/") {
    const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(lcpl, 1);
    g = H5Gcreate2(file, f.group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
    H5Pclose(lcpl);
  }
  const hid_t scalar = H5Screate(H5S_SCALAR);
  if (!skipped(f, "chart")) {
    const hsize_t n = f.chart.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t a = H5Acreate2(g, "chart", H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, f.chart.data());
    H5Aclose(a), H5Sclose(s);
  }
  auto flag = [&](const char* name, long long value) {
    if (skipped(f, name)) return;
    if (f.h5pyStyle) {  // h5py writes numpy.bool_ as an enum {FALSE = 0, TRUE = 1} over int8
      const hid_t e = H5Tenum_create(H5T_NATIVE_SCHAR);
      signed char v0 = 0, v1 = 1, v = static_cast<signed char>(value);
      H5Tenum_insert(e, "FALSE", &v0), H5Tenum_insert(e, "TRUE", &v1);
      const hid_t a = H5Acreate2(g, name, e, scalar, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, e, &v);
      H5Aclose(a), H5Tclose(e);
    } else {
      const hid_t a = H5Acreate2(g, name, H5T_STD_I64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, H5T_NATIVE_LLONG, &value);
      H5Aclose(a);
    }
  };
  flag("periodic_u", f.periodicU);
  flag("periodic_v", f.periodicV);
  if (!f.poles.empty()) {
    const hid_t t = H5Tcopy(H5T_C_S1);
    if (f.h5pyStyle) {
      H5Tset_size(t, H5T_VARIABLE), H5Tset_cset(t, H5T_CSET_UTF8);
      const char* p = f.poles.c_str();
      const hid_t a = H5Acreate2(g, "poles", t, scalar, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, t, &p);
      H5Aclose(a);
    } else {  // fixed length, space padded as Fortran codes write it
      const std::string padded = f.poles + "   ";
      H5Tset_size(t, padded.size()), H5Tset_strpad(t, H5T_STR_SPACEPAD);
      const hid_t a = H5Acreate2(g, "poles", t, scalar, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, t, padded.c_str());
      H5Aclose(a);
    }
    H5Tclose(t);
  }
  const char* names[3] = {"g_uu", "g_uv", "g_vv"};
  const std::vector<double>* data[3] = {&f.guu, &f.guv, &f.gvv};
  for (int k = 0; k < 3; ++k) {
    if (skipped(f, names[k])) continue;
    const hsize_t dims[2] = {static_cast<hsize_t>(f.nv), static_cast<hsize_t>(f.nu)};
    const hid_t s = H5Screate_simple(2, dims, nullptr);
    const hid_t d =
        H5Dcreate2(g, names[k], f.float32 ? H5T_IEEE_F32LE : H5T_IEEE_F64BE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data[k]->data());
    H5Dclose(d), H5Sclose(s);
  }
  if (f.extra) f.extra(g);
  H5Sclose(scalar);
  if (g != file) H5Gclose(g);
  H5Fclose(file);
}

// Torus of revolution (R, r), u = longitude, v = meridian angle: g = diag((R + r cos v)², r²), both axes periodic.
RawField torusSamples(double R, double r, int nu, int nv) {
  RawField f;
  f.nu = nu, f.nv = nv;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double v = 2 * M_PI * j / nv;
      f.guu.push_back((R + r * std::cos(v)) * (R + r * std::cos(v)));
      f.guv.push_back(0);
      f.gvv.push_back(r * r);
    }
  return f;
}

// The Kerr horizon (M = 1) on the cell-centred pole-to-pole grid, from its closed form (docs/metrics.md §2):
// g_φφ = (r₊² + a²)² sin²θ / ρ², g_θθ = ρ², ρ² = r₊² + a² cos²θ, u = φ, v = θ.
RawField kerrSamples(double a, int nu, int nv) {
  RawField f;
  f.nu = nu, f.nv = nv;
  f.chart = {0, 2 * M_PI, 0, M_PI};
  f.periodicU = 1, f.periodicV = 0, f.poles = "both";
  const double rp = 1 + std::sqrt(1 - a * a), s = rp * rp + a * a;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = (j + 0.5) * M_PI / nv, rho2 = rp * rp + a * a * std::cos(th) * std::cos(th);
      f.guu.push_back(s * s * std::sin(th) * std::sin(th) / rho2);
      f.guv.push_back(0);
      f.gvv.push_back(rho2);
    }
  return f;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST_CASE("HDF5 field from the C API: the torus's samples bit for bit, its metric equal to the text format's") {
  const double R = 3, r = 1;
  RawField raw = torusSamples(R, r, 48, 24);
  const fs::path path = dir() / "torus.h5";
  writeRaw(raw, path);
  REQUIRE(isHdf5File(path.string()));
  const SampledField f = readSampledField(path.string());  // dispatched on the signature
  CHECK(f.nu == 48);
  CHECK(f.nv == 24);
  CHECK(f.domain.periodicU);
  CHECK(f.domain.periodicV);
  CHECK_FALSE(f.domain.poleAtV0);
  CHECK(f.domain.u1 == 2 * M_PI);
  // Big-endian float64 on disk, converted by HDF5: exact.
  CHECK(f.guu == raw.guu);
  CHECK(f.guv == raw.guv);
  CHECK(f.gvv == raw.gvv);
  CHECK(f.lines.empty());

  // The text format carries the same samples (17 digits round-trip a double), so both readers give one metric.
  const SampledMetric fromH5(f);
  const SampledMetric fromText(parseSampledField(formatSampledField(f), "torus.txt"));
  for (double u : {0.1, 1.7, 4.0, 6.2})
    for (double v : {0.0, 0.9, 3.3, 5.9}) {
      CHECK(fromH5.g(u, v) == fromText.g(u, v));
      const Eigen::Matrix2d g = fromH5.g(u, v);
      // Fourth-order splines on a 48 × 24 grid of a trigonometric polynomial: within 1e-5 relative of the closed form.
      CHECK(g(0, 0) == Approx((R + r * std::cos(v)) * (R + r * std::cos(v))).epsilon(1e-5));
      CHECK(g(1, 1) == Approx(r * r).epsilon(1e-12));
    }
  // Area of the torus of revolution, 4π²Rr, through the interpolated metric.
  CHECK(integrateOverRectangle(areaDensity(fromH5), 0, 2 * M_PI, 0, 2 * M_PI).value ==
        Approx(4 * M_PI * M_PI * R * r).epsilon(1e-6));
}

TEST_CASE("HDF5 field in a group, h5py's bool and string attributes, float32 data: the Kerr horizon's poles") {
  const double a = 0.95;
  RawField raw = kerrSamples(a, 64, 32);
  raw.group = "/horizons/AhA";
  raw.h5pyStyle = true;
  const fs::path path = dir() / "kerr.h5";
  writeRaw(raw, path);
  const SampledField f = readSampledField(path.string() + ":/horizons/AhA");
  CHECK(f.source == path.string() + ":/horizons/AhA");
  CHECK(f.domain.poleAtV0);
  CHECK(f.domain.poleAtV1);
  CHECK(f.domain.v1 == M_PI);
  CHECK(f.guu == raw.guu);
  CHECK(f.gvv == raw.gvv);
  // The sampled analytic family on the same grid: the same nodes, so the same samples up to the closed form's
  // evaluation order (1e-14 relative).
  const SampledField ref = sampleMetric(KerrNewmanMetric(1, a, 0), 64, 32);
  for (size_t k = 0; k < f.guu.size(); ++k) {
    CHECK(f.guu[k] == Approx(ref.guu[k]).epsilon(1e-14));
    CHECK(f.gvv[k] == Approx(ref.gvv[k]).epsilon(1e-14));
  }
  // Gauss–Bonnet on the whole horizon through the interpolated metric: ∫K dA = 4π (docs/metrics.md: 1e-5 at 128 × 64;
  // the 64 × 32 grid here is within 1e-3).
  const SampledMetric m(f);
  CHECK(integrateOverRectangle(curvatureDensity(m), 0, 2 * M_PI, 0, M_PI).value == Approx(4 * M_PI).epsilon(1e-3));

  RawField single = kerrSamples(a, 64, 32);
  single.float32 = true;
  single.poles = "both";  // fixed-length, space-padded
  writeRaw(single, dir() / "kerr32.h5");
  const SampledField g32 = readSampledFieldHdf5((dir() / "kerr32.h5").string());
  CHECK(g32.domain.poleAtV0);
  for (size_t k = 0; k < g32.guu.size(); ++k) CHECK(g32.guu[k] == static_cast<double>(static_cast<float>(raw.guu[k])));
}

TEST_CASE("conformesh's HDF5 writer round-trips a field exactly, also into a group") {
  const SampledField f = sampleMetric(TorusMetric(2, 0.5), 20, 12);
  const fs::path path = dir() / "written.h5";
  writeSampledFieldHdf5(f, path.string());
  const SampledField back = readSampledField(path.string());
  CHECK(back.nu == f.nu);
  CHECK(back.nv == f.nv);
  CHECK(back.guu == f.guu);
  CHECK(back.guv == f.guv);
  CHECK(back.gvv == f.gvv);
  CHECK(back.domain.periodicU == f.domain.periodicU);
  CHECK(back.domain.periodicV == f.domain.periodicV);
  CHECK(back.domain.u0 == f.domain.u0);
  CHECK(back.domain.v1 == f.domain.v1);

  const SampledField kerr = sampleMetric(KerrNewmanMetric(1, 0.5, 0), 16, 8);
  writeSampledFieldHdf5(kerr, path.string(), "/run1/t100");
  const SampledField kb = readSampledField(path.string() + ":/run1/t100");
  CHECK(kb.domain.poleAtV0);
  CHECK(kb.gvv == kerr.gvv);
}

TEST_CASE("bad HDF5 fields: an InputError naming the file, group and object") {
  const fs::path path = dir() / "bad.h5";
  const std::string p = path.string();
  auto expect = [&](RawField raw, const std::string& message) {
    writeRaw(raw, path);
    const std::string e = errorOf([&] { SampledMetric m(readSampledField(p)); });
    INFO(e);
    CHECK_THAT(e, Contains(p));
    CHECK_THAT(e, Contains(message));
  };
  const RawField good = torusSamples(3, 1, 8, 8);

  RawField f = good;
  f.skip = {"g_uv"};
  expect(f, "missing dataset 'g_uv'");
  f = good;
  f.skip = {"chart"};
  expect(f, "missing attribute 'chart'");
  f = good;
  f.skip = {"periodic_v"};
  expect(f, "missing attribute 'periodic_v'");
  f = good;
  f.chart = {0, 1, 0};
  expect(f, "attribute 'chart' must hold 4 numbers");
  f = good;
  f.chart = {0, 1, 2, 1};
  expect(f, "chart must have finite U0 < U1 and V0 < V1");
  f = good;
  f.periodicU = 2;
  expect(f, "attribute 'periodic_u' must be 0 or 1, found 2");
  f = good;
  f.poles = "north";
  expect(f, "attribute 'poles' must be \"none\" or \"both\", found \"north\"");
  f = good;
  f.poles = "both";  // on a doubly periodic chart
  expect(f, "'poles both' needs periodic_u yes, periodic_v no");
  f = good;
  f.gvv[2 * 8 + 3] = std::nan("");
  expect(f, "dataset 'g_vv' [2][3] (grid node 3, 2) is nan");
  f = good;
  f.guv[5] = 10;  // g_uu g_vv − g_uv² < 0 at node (5, 0)
  expect(f, "grid node (5, 0)");
  // A dataset replaced by an empty one of another rank, shape or type.
  auto replaced = [&](const char* name, std::vector<hsize_t> dims, hid_t type) {
    RawField r = good;
    r.skip = {name};
    r.extra = [name, dims, type](hid_t g) {
      const hid_t s = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
      H5Dclose(H5Dcreate2(g, name, type, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
      H5Sclose(s);
    };
    return r;
  };
  expect(replaced("g_uu", {64}, H5T_IEEE_F64LE), "dataset 'g_uu' must be 2-D with shape (NV, NU), found rank 1");
  expect(replaced("g_uv", {8, 7}, H5T_IEEE_F64LE), "datasets g_uu and g_uv differ in shape: (8, 8) and (8, 7)");
  expect(replaced("g_vv", {8, 8}, H5T_STD_I32LE), "dataset 'g_vv' must hold floating-point numbers, found integer");

  // A group that is not there; a file cut short; the wrong file in an .h5 name.
  writeRaw(good, path);
  CHECK_THAT(errorOf([&] { readSampledField(p + ":/nothing/here"); }), Contains(p + ": no group '/nothing/here'"));
  {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir() / "cut.h5", std::ios::binary) << bytes.substr(0, 600);
  }
  const std::string cut = errorOf([&] { readSampledField((dir() / "cut.h5").string()); });
  CHECK_THAT(cut, Contains((dir() / "cut.h5").string()));
  CHECK_THAT(cut, Contains("corrupt or truncated"));
  std::ofstream(dir() / "text.h5") << "not a field\n";
  CHECK_THAT(errorOf([&] { readSampledFieldHdf5((dir() / "text.h5").string()); }), Contains("not an HDF5 file"));
}
