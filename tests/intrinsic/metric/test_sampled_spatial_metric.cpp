// A spatial 3-metric sampled on a Cartesian grid (sampled_spatial_metric.h): the interpolant reproduces cubic
// polynomials exactly (its stated degree), Kerr–Schild γ written to HDF5 and read back converges at fourth order
// in γ and the horizon area (log–log fits over four spacings) and third order in ∂γ, the induced horizon gives
// 8πMr₊, ∫K dA = 4π and the spin; the ADMBase, CarpetIOHDF5 and SpECTRE namings read the same grid; malformed files
// are named with their dataset and index.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include <hdf5.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/spatial_metric_registry.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"
#include "support/scratch_dir.h"

using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;

namespace {

// γ = I + P(x) with P a symmetric matrix of cubic polynomials (positive definite on the box for the sizes used).
class CubicMetric : public SpatialMetric {
 public:
  std::string name() const override { return "cubic"; }
  std::string description() const override { return "cubic"; }
  Eigen::Matrix3d gamma(const Eigen::Vector3d& x) const override { return jet(x).g; }
  SpatialMetricJet jet(const Eigen::Vector3d& x) const override {
    const double p = 0.1 * x.x() * x.y() * x.z() + 0.05 * std::pow(x.x(), 3), q = 0.02 * x.y() * x.y() * x.z();
    const Eigen::Vector3d dp(0.1 * x.y() * x.z() + 0.15 * x.x() * x.x(), 0.1 * x.x() * x.z(), 0.1 * x.x() * x.y());
    const Eigen::Vector3d dq(0, 0.04 * x.y() * x.z(), 0.02 * x.y() * x.y());
    SpatialMetricJet j;
    j.g = Eigen::Matrix3d::Identity() * 2;
    j.g(0, 0) += p, j.g(1, 2) = j.g(2, 1) = q;
    for (int k = 0; k < 3; ++k) {
      j.d[k].setZero();
      j.d[k](0, 0) = dp[k], j.d[k](1, 2) = j.d[k](2, 1) = dq[k];
    }
    return j;
  }
};

double kerrSpheroid(double a, double t) {
  const double rp = 1 + std::sqrt(1 - a * a);
  return 1 / std::sqrt(std::pow(std::sin(t), 2) / (rp * rp + a * a) + std::pow(std::cos(t), 2) / (rp * rp));
}

// A box [−L, L]³ with n nodes per axis; n even, so no node lies on z = 0 (where the Kerr ring is).
SpatialMetricGrid kerrGrid(double a, int n, double L = 2.7) {
  const double h = 2 * L / (n - 1);
  return sampleSpatialMetric(KerrSchildMetric(1.0, a, Eigen::Vector3d::Zero()), {n, n, n}, Eigen::Vector3d::Constant(-L),
                             Eigen::Vector3d::Constant(h), "kerr-schild grid");
}

std::string scratch(const std::string& name) {
  return (conformesh::testing::scratchDir() / name).string();
}

}  // namespace

TEST_CASE("sampled spatial metric: cubic polynomials are reproduced to round-off") {
  const CubicMetric cubic;
  const SampledSpatialMetric s(sampleSpatialMetric(cubic, {8, 9, 10}, Eigen::Vector3d(-1, -1.2, -0.9),
                                                   Eigen::Vector3d(0.3, 0.27, 0.21)));
  double err = 0, derr = 0;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d t(std::fmod(n * 0.6180339887, 1.0), std::fmod(n * 0.41421356, 1.0),
                            std::fmod(n * 0.7320508, 1.0));
    const Eigen::Vector3d x = s.lower() + t.cwiseProduct(s.upper() - s.lower());
    const SpatialMetricJet a = s.jet(x), b = cubic.jet(x);
    err = std::max(err, (a.g - b.g).cwiseAbs().maxCoeff());
    for (int k = 0; k < 3; ++k) derr = std::max(derr, (a.d[k] - b.d[k]).cwiseAbs().maxCoeff());
  }
  // Exact in exact arithmetic (Hermite cubic with fourth-order differences reproduces cubics); 1e-13 is round-off of
  // 216-term sums of O(1) values and of dividing by h ≈ 0.2.
  CHECK(err < 1e-13);
  CHECK(derr < 1e-12);
  CHECK_THROWS_WITH(s.gamma(s.upper() + Eigen::Vector3d(0.01, 0, 0)), Contains("outside the interpolation box"));
}

TEST_CASE("sampled spatial metric: Kerr-Schild through HDF5, fourth order in gamma and in the horizon area") {
  const double a = 0.8, rp = 1 + std::sqrt(1 - a * a);
  const KerrSchildMetric exact(1.0, a, Eigen::Vector3d::Zero());
  const Strahlkorper shape = fitStrahlkorper([&](double t, double) { return kerrSpheroid(a, t); }, 16,
                                             Eigen::Vector3d::Zero());
  std::vector<double> h, gErr, dErr, areaErr;
  for (int n : {24, 32, 48, 64}) {
    const std::string path = scratch("ks" + std::to_string(n) + ".h5");
    writeSpatialMetricHdf5(kerrGrid(a, n), path, "/iteration0");
    std::shared_ptr<const SpatialMetric> gamma = makeSpatialMetric(path + ":/iteration0", {});
    h.push_back(5.4 / (n - 1));
    // Pointwise errors on the horizon itself, where the surface samples γ.
    double eg = 0, ed = 0;
    for (int k = 0; k < 400; ++k) {
      const Eigen::Vector3d x = shape.point(M_PI * (k + 0.5) / 400, 2.399963 * k);
      const SpatialMetricJet s = gamma->jet(x), e = exact.jet(x);
      eg = std::max(eg, (s.g - e.g).cwiseAbs().maxCoeff());
      for (int c = 0; c < 3; ++c) ed = std::max(ed, (s.d[c] - e.d[c]).cwiseAbs().maxCoeff());
    }
    gErr.push_back(eg), dErr.push_back(ed);
    const HorizonSurfaceMetric m(shape, gamma);
    const double area = metricArea(m).value;
    areaErr.push_back(std::abs(area / (8 * M_PI * rp) - 1));
    std::printf("n=%d h=%.4f |dgamma|=%.3e |d dgamma|=%.3e area rel err=%.3e\n", n, h.back(), eg, ed, areaErr.back());
  }
  const double sg = fitLogLogSlope(h, gErr), sd = fitLogLogSlope(h, dErr), sa = fitLogLogSlope(h, areaErr);
  std::printf("slopes: gamma %.2f, d gamma %.2f, area %.2f\n", sg, sd, sa);
  // Stated orders 4 (γ, area) and 3 (∂γ); 0.5 below them allows the pre-asymptotic coarsest grid (h = 0.23, the
  // stencil reaching within 0.3 of the ring singularity).
  CHECK(sg >= 3.5);
  CHECK(sa >= 3.5);
  CHECK(sd >= 2.5);
  CHECK(areaErr.back() < 1e-5);
}

TEST_CASE("sampled spatial metric: the horizon in a sampled Kerr-Schild gamma, Gauss-Bonnet and spin") {
  for (double a : {0.3, 0.6, 0.9}) {
    const double rp = 1 + std::sqrt(1 - a * a);
    const Strahlkorper shape = fitStrahlkorper([&](double t, double) { return kerrSpheroid(a, t); }, 16,
                                               Eigen::Vector3d::Zero());
    const HorizonSurfaceMetric m(shape, std::make_shared<SampledSpatialMetric>(kerrGrid(a, 40)));
    HorizonDiagnosticsOptions o;
    o.areaTolerance = 1e-8;  // the area is checked to 1e-5 here; 1e-10 would cost ten times the evaluations
    const HorizonDiagnostics d = horizonDiagnostics(m, o);
    // K comes from differenced first derivatives of a C¹ interpolant (∂γ only C⁰): the adaptive quadrature is asked
    // for 1e-6 only, with a budget of 10⁵ evaluations (seconds, not minutes).
    QuadratureOptions q;
    q.absoluteTolerance = q.relativeTolerance = 1e-6;
    q.maxEvaluations = 100'000;
    q.throwOnFailure = false;
    const double totalK = metricTotalCurvature(m, q).value;
    std::printf("a=%.1f area rel err %.3e, int K dA - 4pi = %.3e, spin - a = %.3e\n", a,
                d.area / (8 * M_PI * rp) - 1, totalK - 4 * M_PI, d.spin - a);
    CHECK(std::abs(d.area / (8 * M_PI * rp) - 1) < 1e-5);
    CHECK(std::abs(totalK - 4 * M_PI) < 1e-3 * 4 * M_PI);
    CHECK(std::abs(d.spin - a) < 1e-3);  // the requirement
  }
}

TEST_CASE("sampled spatial metric: ADMBase, Carpet and SpECTRE dataset names read the same grid") {
  const SpatialMetricGrid g = kerrGrid(0.6, 8);
  const std::string adm = scratch("adm.h5"), spectre = scratch("spectre.h5"), carpet = scratch("carpet.h5");
  writeSpatialMetricHdf5(g, adm);
  writeSpatialMetricHdf5(g, spectre, "/", "spectre");
  writeSpatialMetricHdf5(g, carpet);
  {  // Carpet's names, and origin/delta only on the datasets (as CarpetIOHDF5 writes them).
    const hid_t f = H5Fopen(carpet.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    for (const auto& c : spatialMetricComponentNames("admbase"))
      H5Lmove(f, c.c_str(), f, ("ADMBASE::" + c + " it=0 tl=0 rl=0 c=0").c_str(), H5P_DEFAULT, H5P_DEFAULT);
    H5Adelete(f, "origin");
    H5Adelete(f, "delta");
    H5Fclose(f);
  }
  for (const std::string& p : {adm, spectre, carpet}) {
    const SpatialMetricGrid r = readSpatialMetricHdf5(p);
    CHECK(r.n == g.n);
    CHECK(r.origin == g.origin);
    CHECK(r.delta == g.delta);
    for (int c = 0; c < 6; ++c) CHECK(r.g[c] == g.g[c]);
  }
}

TEST_CASE("sampled spatial metric: malformed files are named with dataset and index") {
  SpatialMetricGrid g = kerrGrid(0.6, 8);
  const std::string path = scratch("bad.h5");
  SECTION("missing dataset") {
    writeSpatialMetricHdf5(g, path);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(f, "gyz", H5P_DEFAULT);
    H5Fclose(f);
    CHECK_THROWS_WITH(readSpatialMetricHdf5(path), Contains(path) && Contains("missing dataset 'gyz'"));
  }
  SECTION("wrong shape") {
    writeSpatialMetricHdf5(g, path);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(f, "gzz", H5P_DEFAULT);
    const hsize_t dims[3] = {8, 8, 7};
    const std::vector<double> ones(8 * 8 * 7, 1.0);
    const hid_t space = H5Screate_simple(3, dims, nullptr);
    const hid_t d = H5Dcreate2(f, "gzz", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ones.data());
    H5Dclose(d), H5Sclose(space), H5Fclose(f);
    CHECK_THROWS_WITH(readSpatialMetricHdf5(path),
                      Contains("'gxx' and 'gzz' differ in shape: (8, 8, 8) and (8, 8, 7)"));
  }
  SECTION("not positive definite") {
    g.g[1][g.index(3, 4, 5)] = 5;  // gxy > √(gxx gyy)
    writeSpatialMetricHdf5(g, path);
    CHECK_THROWS_WITH(readSpatialMetricHdf5(path), Contains("not positive definite") && Contains("[5][4][3]") &&
                                                       Contains("gxx*gyy - gxy^2"));
  }
  SECTION("NaN") {
    g.g[4][g.index(1, 2, 6)] = std::nan("");
    writeSpatialMetricHdf5(g, path, "/", "spectre");
    CHECK_THROWS_WITH(readSpatialMetricHdf5(path), Contains("dataset 'SpatialMetric_yz' [6][2][1]") &&
                                                       Contains("must be finite"));
  }
  SECTION("missing attribute, too few nodes, missing file") {
    writeSpatialMetricHdf5(g, path);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Adelete(f, "delta");
    const hid_t d = H5Dopen2(f, "gxx", H5P_DEFAULT);
    H5Adelete(d, "delta");
    H5Dclose(d), H5Fclose(f);
    CHECK_THROWS_WITH(readSpatialMetricHdf5(path), Contains("no attribute 'delta' on dataset 'gxx' nor on the group"));
    CHECK_THROWS_WITH(makeSpatialMetric(scratch("absent.h5"), {}), Contains("cannot open"));
    CHECK_THROWS_WITH(makeSpatialMetric(path, {{"M", 1}}), Contains("takes no --param"));
    SpatialMetricGrid small = kerrGrid(0.6, 8);
    small.n[0] = 5;
    CHECK_THROWS_WITH(SampledSpatialMetric(small), Contains("at least 6"));
  }
}
