// Tests for strahlkorper_io.h: HDF5 shape groups round-trip bit for bit (coefficients and metadata); a file written
// with the HDF5 C API directly (as h5py would: center as a dataset, variable-length strings) reads to the same shape;
// the sampled θ–φ radius of the Kerr–Schild horizon spheroid gives Smarr's area 8πMr₊ with the error falling
// spectrally in l_max (log-linear fit) on Gauss–Legendre and uniform θ nodes; band-limited samples are fitted exactly;
// malformed files are InputErrors naming the file, group, dataset and element.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <unistd.h>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/spatial_metric.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
namespace fs = std::filesystem;

namespace {

std::function<double(double, double)> kerrSpheroid(double M, double a) {  // r = r₊ of Kerr–Schild, as r(θ)
  const double rp = M + std::sqrt(M * M - a * a), A2 = rp * rp + a * a, C2 = rp * rp;
  return [=](double theta, double) {
    const double s = std::sin(theta), c = std::cos(theta);
    return 1 / std::sqrt(s * s / A2 + c * c / C2);
  };
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "conformesh_test_strahlkorper_io";
  fs::create_directories(d);
  return d / name;
}

double relativeAreaError(const Strahlkorper& s, double a) {
  QuadratureOptions q;
  q.relativeTolerance = 1e-13, q.absoluteTolerance = 1e-13;
  const double exact = 8 * M_PI * (1 + std::sqrt(1 - a * a));
  return std::abs(
             metricArea(HorizonSurfaceMetric(s, std::make_shared<KerrSchildMetric>(1.0, a, Eigen::Vector3d::Zero())), q)
                 .value -
             exact) /
         exact;
}

// Least-squares slope of log(err) against l_max (errors floored at 1e-15, round-off).
double logLinearSlope(const std::vector<int>& l, const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(l.size());
  for (size_t i = 0; i < l.size(); ++i) {
    const double x = l[i], y = std::log(std::max(err[i], 1e-15));
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Raw HDF5 writing, independent of conformesh's writer.
struct RawFile {
  hid_t f;
  explicit RawFile(const fs::path& p) : f(H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)) {}
  ~RawFile() { H5Fclose(f); }
  hid_t group(const char* name) { return H5Gcreate2(f, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT); }
};
void rawDataset(hid_t g, const char* name, const std::vector<double>& v, std::vector<hsize_t> dims) {
  const hid_t s = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t d = H5Dcreate2(g, name, H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(d), H5Sclose(s);
}
void rawVarString(hid_t g, const char* name, const char* value) {  // h5py's default string attribute
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  const hid_t s = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(g, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, t, &value);
  H5Aclose(a), H5Sclose(s), H5Tclose(t);
}
void rawScalar(hid_t g, const char* name, double v) {
  const hid_t s = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(g, name, H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a), H5Sclose(s);
}

std::string errorOf(const std::string& pathAndGroup) {
  try {
    readHorizonShape(pathAndGroup);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("strahlkorper io: HDF5 groups round-trip coefficients and metadata bit for bit") {
  const fs::path p = scratch("roundtrip.h5");
  std::vector<HorizonShapeGroup> groups(2);
  groups[0].group = "/t000";
  groups[0].record.shape = fitStrahlkorper(kerrSpheroid(1, 0.8), 16, Eigen::Vector3d(0.7, -1.3, 2.1));
  groups[0].record.meta.hasTime = true, groups[0].record.meta.time = 12.5;
  groups[0].record.meta.params = {{"M", 1.0}, {"a", 0.8}};
  groups[1].group = "/deep/t001";  // nested, with a non-axisymmetric shape
  groups[1].record.shape = Strahlkorper(Eigen::Vector3d::Zero(), {{0, 0, 7.0}, {2, -1, 0.1}, {3, 2, -0.05}});
  groups[1].record.meta.spatialMetric = "flat";
  writeHorizonShapesHdf5(p.string(), groups);
  CHECK(listHorizonShapeGroups(p.string()) == std::vector<std::string>{"/deep/t001", "/t000"});
  for (const auto& g : groups) {
    const HorizonShapeRecord r = readHorizonShape(p.string() + ":" + g.group);
    CHECK_FALSE(r.sampled);
    CHECK(r.shape.center() == g.record.shape.center());
    const auto a = r.shape.terms(), b = g.record.shape.terms();
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) CHECK((a[i].l == b[i].l && a[i].m == b[i].m && a[i].a == b[i].a));
    CHECK(r.meta.spatialMetric == g.record.meta.spatialMetric);
    CHECK(r.meta.params == g.record.meta.params);
    CHECK(r.meta.hasTime == g.record.meta.hasTime);
    CHECK(r.meta.time == g.record.meta.time);
    CHECK(readHorizonMetadata(p.string() + ":" + g.group).params == g.record.meta.params);
  }
  // The HDF5 shape is the same Kerr horizon: Smarr's area to the l_max = 16 fit's 1e-12 (docs/horizons.md §3).
  const HorizonShapeRecord r = readHorizonShape(p.string() + ":/t000");
  QuadratureOptions q;
  q.relativeTolerance = 1e-13, q.absoluteTolerance = 1e-13;
  auto gamma = std::make_shared<KerrSchildMetric>(1.0, 0.8, Eigen::Vector3d(0.7, -1.3, 2.1));
  CHECK(metricArea(HorizonSurfaceMetric(r.shape, gamma), q).value == Approx(8 * M_PI * 1.6).epsilon(1e-12));
}

TEST_CASE("strahlkorper io: an h5py-style file (center dataset, variable-length strings) reads") {
  const fs::path p = scratch("h5py.h5");
  {
    RawFile f(p);
    const hid_t g = f.group("/AhA");
    rawDataset(g, "center", {1, 2, 3}, {3});
    // Condon–Shortley coefficients: a_11 = −0.2 with the phase is +0.2 in ours, a_20 unchanged.
    rawDataset(g, "coefficients", {0, 0, 7, 1, 1, -0.2, 2, 0, 0.3}, {3, 3});
    rawVarString(g, "convention", "orthonormal-condon-shortley");
    rawVarString(g, "spatial_metric", "schwarzschild-isotropic");
    rawScalar(g, "time", 3.25);
    rawScalar(g, "param_M", 2.0);
    H5Gclose(g);
  }
  const HorizonShapeRecord r = readHorizonShape(p.string() + ":/AhA");
  CHECK(r.shape.center() == Eigen::Vector3d(1, 2, 3));
  CHECK(r.shape.coefficient(0, 0) == 7);
  CHECK(r.shape.coefficient(1, 1) == 0.2);
  CHECK(r.shape.coefficient(2, 0) == 0.3);
  CHECK(r.meta.spatialMetric == "schwarzschild-isotropic");
  CHECK(r.meta.time == 3.25);
  CHECK(r.meta.params.at("M") == 2.0);
}

TEST_CASE("strahlkorper io: band-limited samples are fitted exactly on both node sets") {
  const Strahlkorper s(Eigen::Vector3d(0.1, 0, 0), {{0, 0, 6.0}, {1, -1, 0.2}, {3, 2, -0.1}, {5, -4, 0.03}});
  for (ThetaNodes nodes : {ThetaNodes::GaussLegendre, ThetaNodes::Uniform}) {
    const RadiusFit f = fitSampledRadius(sampleStrahlkorper(s, nodes, 8, 16), 7, "test");
    CHECK(f.lMax == 7);
    CHECK(f.maxResidual < 1e-13);  // round-off of an exact projection / consistent least squares
    for (int l = 0; l <= 7; ++l)
      for (int m = -l; m <= l; ++m) CHECK(std::abs(f.shape.coefficient(l, m) - s.coefficient(l, m)) < 1e-13);
  }
}

TEST_CASE("strahlkorper io: the sampled Kerr-Schild spheroid gives Smarr's area, spectrally in l_max") {
  const double a = 0.8;
  const std::vector<int> ls = {4, 8, 12, 16};
  for (ThetaNodes nodes : {ThetaNodes::GaussLegendre, ThetaNodes::Uniform}) {
    std::vector<double> err, residual;
    for (int l : ls) {
      SampledRadius s;
      s.nodes = nodes;
      // The minimal grid of l_max: l_max + 1 θ nodes × 2 l_max + 2 φ nodes (aliasing included).
      const std::vector<double> theta = thetaNodes(nodes, l + 1);
      s.r.resize(l + 1, 2 * l + 2);
      for (int i = 0; i <= l; ++i)
        for (int k = 0; k < 2 * l + 2; ++k) s.r(i, k) = kerrSpheroid(1, a)(theta[i], 0);
      const RadiusFit f = fitSampledRadius(s, -1, "test");
      REQUIRE(f.lMax == l);
      err.push_back(relativeAreaError(f.shape, a));
      residual.push_back(f.maxResidual);
    }
    const double slope = logLinearSlope(ls, err);
    UNSCOPED_INFO(toString(nodes) << ": area errors " << err[0] << " " << err[1] << " " << err[2] << " " << err[3]
                                  << ", slope of log(err) in l_max " << slope << "; residuals " << residual[0] << " "
                                  << residual[3]);
    // Spectral: log(err) linear in l_max with slope ≤ −1 (a factor e per unit of l_max; an algebraic rate l^−p
    // would flatten); at l_max = 16 below 1e-9.
    CHECK(slope < -1.0);
    CHECK(err.back() < 1e-9);
    CHECK(residual.back() < 1e-6);
  }
}

TEST_CASE("strahlkorper io: sampled radius in JSON") {
  const fs::path p = scratch("sampled.json");
  const SampledRadius s = sampleStrahlkorper(Strahlkorper(Eigen::Vector3d::Zero(), {{0, 0, 5.0}, {2, 0, 0.1}}),
                                             ThetaNodes::GaussLegendre, 5, 10);
  {
    std::ofstream out(p);
    out << "{\"center\": [0, 0, 0], \"theta_nodes\": \"gauss-legendre\", \"l_max\": 4, \"time\": 2, \"radius\": [";
    for (int i = 0; i < 5; ++i) {
      out << (i ? ", [" : "[");
      for (int k = 0; k < 10; ++k) out << (k ? ", " : "") << std::setprecision(17) << s.r(i, k);
      out << "]";
    }
    out << "]}";
  }
  const HorizonShapeRecord r = readHorizonShape(p.string());
  CHECK(r.sampled);
  CHECK(r.fit.lMax == 4);
  CHECK(std::abs(r.shape.coefficient(2, 0) - 0.1) < 1e-14);
  CHECK(r.meta.time == 2);
  std::ofstream(p) << "{\"center\": [0, 0, 0], \"radius\": [[1, 1, 1], [1, -2, 1]]}";
  CHECK_THAT(errorOf(p.string()),
             Catch::Contains(p.string()) && Catch::Contains("radius[1][1]") && Catch::Contains("positive"));
}

TEST_CASE("strahlkorper io: malformed HDF5 shapes name the file, dataset and element") {
  const fs::path p = scratch("bad.h5");
  {
    RawFile f(p);
    hid_t g = f.group("/nocoef");
    rawDataset(g, "center", {0, 0, 0}, {3});
    H5Gclose(g);
    g = f.group("/shape");
    rawDataset(g, "center", {0, 0, 0}, {3});
    rawDataset(g, "coefficients", {0, 0, 7, 1, 1}, {5});
    H5Gclose(g);
    g = f.group("/nan");
    rawDataset(g, "center", {0, 0, 0}, {3});
    rawDataset(g, "coefficients", {0, 0, 7, 2, 1, std::nan("")}, {2, 3});
    H5Gclose(g);
    g = f.group("/negative");
    rawDataset(g, "center", {0, 0, 0}, {3});
    rawDataset(g, "radius", {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, -0.5, 1}, {3, 4});
    H5Gclose(g);
    g = f.group("/shrunk");  // r = a_00 Y_00 + a_10 Y_10 < 0 near θ = π
    rawDataset(g, "center", {0, 0, 0}, {3});
    rawDataset(g, "coefficients", {0, 0, 1, 1, 0, 3}, {2, 3});
    H5Gclose(g);
    g = f.group("/nocenter");
    rawDataset(g, "coefficients", {0, 0, 7}, {1, 3});
    H5Gclose(g);
  }
  const std::string f = p.string();
  CHECK_THAT(errorOf(f + ":/nocoef"),
             Catch::Contains(f + ":/nocoef") && Catch::Contains("missing dataset 'coefficients'"));
  CHECK_THAT(errorOf(f + ":/shape"), Catch::Contains(f + ":/shape") && Catch::Contains("'coefficients'") &&
                                         Catch::Contains("(n, 3)") && Catch::Contains("found (1, 5)"));
  CHECK_THAT(errorOf(f + ":/nan"), Catch::Contains("'coefficients' row 1") && Catch::Contains("nan"));
  CHECK_THAT(errorOf(f + ":/negative"), Catch::Contains(f + ":/negative: dataset 'radius'") &&
                                            Catch::Contains("radius[2][2]") && Catch::Contains("positive"));
  CHECK_THAT(errorOf(f + ":/shrunk"), Catch::Contains(f + ":/shrunk") && Catch::Contains("must be positive"));
  CHECK_THAT(errorOf(f + ":/nocenter"), Catch::Contains("missing 'center'"));
  CHECK_THAT(errorOf(f + ":/absent"), Catch::Contains("no group '/absent'"));
  CHECK(listHorizonShapeGroups(f).size() == 6);  // every marked group is listed, so a series reports each in its row
  std::ofstream(scratch("fake.h5")) << "not hdf5";
  CHECK_THAT(errorOf(scratch("fake.h5").string()), Catch::Contains("not an HDF5 file"));
}

TEST_CASE("strahlkorper io: SpECTRE's Spherepack coefficients give SpECTRE's documented expansion") {
  // f = ½ P̄_0^0 a(0,0) + ½ P̄_2^0 a(0,2) + P̄_1^1 a(1,1) cos φ − P̄_2^1 b(1,2) sin φ − P̄_3^2 b(2,3) sin 2φ with
  // P̄_l^m = (−1)^m √((2l+1)(l−m)!/(2(l+m)!)) P_l^m and Jackson's P_l^m (Condon–Shortley phase), in closed form:
  // P_0^0 = 1, P_2^0 = (3x² − 1)/2, P_1^1 = −s, P_2^1 = −3xs, P_3^2 = 15 x s² (x = cos θ, s = sin θ).
  const double a00 = 8, a02 = 0.3, a11 = -0.2, b12 = 0.15, b23 = 0.05;
  const auto pbar = [](int l, int m, double P) {
    double ratio = 1;  // (l − m)!/(l + m)!
    for (int k = l - m + 1; k <= l + m; ++k) ratio /= k;
    return (m % 2 ? -1.0 : 1.0) * std::sqrt((2 * l + 1) * ratio / 2) * P;
  };
  const auto spectre = [&](double t, double p) {
    const double x = std::cos(t), s = std::sin(t);
    return 0.5 * pbar(0, 0, 1) * a00 + 0.5 * pbar(2, 0, (3 * x * x - 1) / 2) * a02 +
           pbar(1, 1, -s) * a11 * std::cos(p) - pbar(2, 1, -3 * x * s) * b12 * std::sin(p) -
           pbar(3, 2, 15 * x * s * s) * b23 * std::sin(2 * p);
  };
  const std::string text = R"({"center": [0, 0, 0], "convention": "spectre-spherepack", "coefficients": [[0, 0, 8], )"
                           R"([2, 0, 0.3], [1, 1, -0.2], [2, -1, 0.15], [3, -2, 0.05]]})";
  const Strahlkorper s = parseStrahlkorperJson(text, "spectre.json");
  for (double t : {0.3, 1.1, 2.5})
    for (double p : {0.2, 2.0, 4.4}) CHECK(s.radius(t, p).r == Approx(spectre(t, p)).epsilon(1e-14));
}
