// test_sampled_metric.cpp — sampled metric fields: the Kerr horizon sampled on a 64 × 128 grid reproduces ∫K dA over
// polar caps (closed form by Gauss–Bonnet) with the order measured over four grids; periodic and rectangular fields;
// the text format round-trips; every kind of bad input is an InputError naming FILE:LINE.
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/field_check.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

namespace {

// ∫K dA over the cap θ ≤ θc of the Kerr–Newman horizon, by Gauss–Bonnet: 2π − ∮k_g = 2π (1 − (√G)_θ/√E) with
// (√G)_θ/√E = (r₊² + a²)² cos θc / ρ⁴ (docs/metrics.md).
double kerrCapCurvature(const KerrNewmanMetric& k, double a, double thetaC) {
  const double rp = k.horizonRadius(), s = rp * rp + a * a,
               rho2 = rp * rp + a * a * std::cos(thetaC) * std::cos(thetaC);
  return 2 * M_PI * (1 - s * s * std::cos(thetaC) / (rho2 * rho2));
}


const char* kGood =
    "conformesh-metric-field 1\n"
    "# a flat 4x4 rectangle\n"
    "chart 0 3 0 3\n"
    "grid 4 4\n"
    "periodic_u no\n"
    "periodic_v no\n"
    "fields g_vv g_uu g_uv\n"
    "data\n";

std::string flatData(int n, const std::string& replaceLine = "", int at = -1) {
  std::string s;
  for (int k = 0; k < n; ++k) s += (k == at ? replaceLine : std::string("1 1 0")) + "\n";
  return s;
}

}  // namespace

TEST_CASE("sampled Kerr horizon (64 x 128): polar-cap curvature to the accuracy of its resolution, with its order") {
  const double a = 0.95;
  const KerrNewmanMetric kerr(1.0, a, 0.0);
  const std::vector<double> caps = {0.3, M_PI / 3, M_PI / 2};
  std::vector<double> h, err;
  for (int nv : {8, 16, 32, 64}) {
    const SampledMetric field(sampleMetric(kerr, 2 * nv, nv));
    double worst = 0;
    for (double tc : caps) {
      const double exact = kerrCapCurvature(kerr, a, tc);
      const double got = integrateOverRectangle(curvatureDensity(field), 0, 2 * M_PI, 0, tc).value;
      worst = std::max(worst, std::abs(got - exact));
    }
    h.push_back(M_PI / nv);
    err.push_back(worst);
    std::cout << "sampled kerr a=0.95 grid " << 2 * nv << " x " << nv << ": max |cap integral error| = " << worst
              << "\n";
  }
  const double p = fitLogLogSlope(h, err);
  std::cout << "sampled kerr: cap-curvature order " << p << "\n";
  // K uses second derivatives of a cubic spline: second order at least.
  CHECK(p > 1.8);
  CHECK(err.back() < 1e-3);
  // The whole sphere: Gauss–Bonnet 4π and the area 8πMr₊ survive sampling.
  const SampledMetric f64(sampleMetric(kerr, 128, 64));
  CHECK(metricTotalCurvature(f64).value == Approx(4 * M_PI).epsilon(1e-5));
  CHECK(metricArea(f64).value == Approx(kerr.area()).epsilon(1e-6));
  // The interpolant is exact at the samples and smooth through the poles (g_uu ∝ sin²v exactly).
  const SampledField sf = sampleMetric(kerr, 128, 64);
  CHECK(f64.g(sf.nodeU(5), sf.nodeV(3))(0, 0) == Approx(sf.guu[3 * 128 + 5]).epsilon(1e-12));
  CHECK(f64.g(1.0, 0.0)(0, 0) == 0);
  CHECK(f64.gaussianCurvature(0.3, 1e-3) == Approx(kerr.gaussianCurvature(0, 1e-3)).epsilon(1e-3));
}

TEST_CASE("sampled fields discretize like analytic ones (closed sphere, Gauss-Bonnet)") {
  const KerrNewmanMetric kerr(1.0, 1.0, 0.0);
  const SampledMetric field(sampleMetric(kerr, 64, 32));
  DiscretizationOptions o;
  o.resolution = 8;
  const MeshData t0 = discretizeMetric(field, o);
  const IntrinsicTriangulation tri = toTriangulation(t0);
  CHECK(tri.mesh.eulerCharacteristic() == 2);
  CHECK(std::abs(curvatureTotals(tri).gaussBonnetResidual) < 1e-10);
  CHECK(totalArea(tri) == Approx(kerr.area()).epsilon(5e-3));
}

TEST_CASE("periodic and rectangular fields: torus total curvature, text round trip") {
  const TorusMetric torus(3, 1);
  const SampledField sf = sampleMetric(torus, 48, 32);
  const SampledField back = parseSampledField(formatSampledField(sf), "torus.txt");
  REQUIRE(back.nu == 48);
  REQUIRE(back.domain.periodicU);
  REQUIRE(back.domain.periodicV);
  for (size_t k = 0; k < sf.guu.size(); ++k) REQUIRE(back.guu[k] == sf.guu[k]);
  const SampledMetric m(back);
  CHECK(std::abs(metricTotalCurvature(m).value) < 1e-8);
  CHECK(metricArea(m).value == Approx(4 * M_PI * M_PI * 3).epsilon(1e-7));
  // Not-a-knot splines reproduce cubics exactly: g = diag(1 + u³, 2 + v²) sampled on 6 × 5 nodes.
  SampledField cubic;
  cubic.source = "cubic";
  cubic.domain.u0 = 0, cubic.domain.u1 = 1, cubic.domain.v0 = 0, cubic.domain.v1 = 2;
  cubic.nu = 6, cubic.nv = 5;
  for (int j = 0; j < cubic.nv; ++j)
    for (int i = 0; i < cubic.nu; ++i) {
      const double u = cubic.nodeU(i), v = cubic.nodeV(j);
      cubic.guu.push_back(1 + u * u * u), cubic.guv.push_back(0.1 * u * v), cubic.gvv.push_back(2 + v * v);
    }
  const SampledMetric cm(cubic);
  const MetricJet j = cm.jet(0.37, 1.23);
  CHECK(j.g(0, 0) == Approx(1 + 0.37 * 0.37 * 0.37).epsilon(1e-13));
  CHECK(j.guu(0, 0) == Approx(6 * 0.37).epsilon(1e-12));
  CHECK(j.guv(0, 1) == Approx(0.1).epsilon(1e-12));
  CHECK(j.gvv(1, 1) == Approx(2).epsilon(1e-12));
}

TEST_CASE("bad metric fields: each kind of error names FILE:LINE") {
  using Catch::Contains;
  CHECK_NOTHROW(SampledMetric(parseSampledField(std::string(kGood) + flatData(16), "f.txt")));
  // Not positive definite at data line 5 (file line 13): g_vv g_uu g_uv = 1 1 2.
  REQUIRE_THROWS_WITH(SampledMetric(parseSampledField(std::string(kGood) + flatData(16, "1 1 2", 4), "f.txt")),
                      Contains("f.txt:13") && Contains("not positive definite"));
  // Negative g_uu.
  REQUIRE_THROWS_WITH(SampledMetric(parseSampledField(std::string(kGood) + flatData(16, "1 -1 0", 0), "f.txt")),
                      Contains("f.txt:9") && Contains("not positive definite"));
  // NaN.
  REQUIRE_THROWS_WITH(SampledMetric(parseSampledField(std::string(kGood) + flatData(16, "nan 1 0", 2), "f.txt")),
                      Contains("f.txt:11") && Contains("not finite"));
  // Wrong grid shape: too few and too many lines; too small a grid.
  REQUIRE_THROWS_WITH(parseSampledField(std::string(kGood) + flatData(15), "f.txt"),
                      Contains("f.txt:") && Contains("wrong grid shape") && Contains("found 15"));
  REQUIRE_THROWS_WITH(parseSampledField(std::string(kGood) + flatData(17), "f.txt"),
                      Contains("f.txt:25") && Contains("more data lines"));
  std::string small = kGood;
  small.replace(small.find("grid 4 4"), 8, "grid 2 8");
  REQUIRE_THROWS_WITH(SampledMetric(parseSampledField(small + flatData(16), "f.txt")),
                      Contains("f.txt") && Contains("wrong grid shape"));
  // Missing field.
  std::string missing = kGood;
  missing.replace(missing.find("fields g_vv g_uu g_uv"), 21, "fields g_vv g_uu");
  REQUIRE_THROWS_WITH(parseSampledField(missing + flatData(16), "f.txt"),
                      Contains("f.txt:7") && Contains("missing field 'g_uv'"));
  // Data line with the wrong number of columns; a non-number; an unknown key; no header.
  REQUIRE_THROWS_WITH(parseSampledField(std::string(kGood) + flatData(16, "1 1", 3), "f.txt"),
                      Contains("f.txt:12") && Contains("must have 3 numbers"));
  REQUIRE_THROWS_WITH(parseSampledField(std::string(kGood) + flatData(16, "1 x 0", 3), "f.txt"),
                      Contains("f.txt:12") && Contains("g_uu must be a number"));
  REQUIRE_THROWS_WITH(parseSampledField("conformesh-metric-field 1\nsize 4 4\n", "f.txt"),
                      Contains("f.txt:2") && Contains("unknown key 'size'"));
  REQUIRE_THROWS_WITH(parseSampledField("hello\n", "f.txt"), Contains("f.txt:1") && Contains("header"));
  REQUIRE_THROWS_WITH(readSampledField("/nonexistent/field.txt"), Contains("/nonexistent/field.txt"));
  // Pole-to-pole fields need an even NU.
  const KerrNewmanMetric kerr(1.0, 0.5, 0.0);
  REQUIRE_THROWS_WITH(SampledMetric(sampleMetric(kerr, 15, 8)), Contains("even NU"));
}

// The mistakes of handing a horizon over (field_check.h), each made on the Kerr field sampled at a/M = 0.95, 64 × 32:
// each is refused with an error that names the mistake, where before it was meshed as an annulus, hung, or blamed on
// the resolution. The correct field passes all of them, and `checkField` reports its closed forms.
namespace {

using Catch::Contains;

std::string fieldError(const SampledField& f) {
  try {
    SampledMetric m(f);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

SampledField kerrField() {
  SampledField f = sampleMetric(KerrNewmanMetric(1.0, 0.95, 0.0), 64, 32);
  f.source = "kerr.txt";
  return f;
}

}  // namespace

TEST_CASE("field checks: a sphere chart without `poles both` is refused with 'is this a sphere?'") {
  SampledField f = kerrField();
  f.domain.poleAtV0 = f.domain.poleAtV1 = false;  // the 'poles both' line left out: v-nodes read as j·π/(NV − 1)
  CHECK_THAT(fieldError(f), Contains("kerr.txt") && Contains("is this a sphere? add `poles both`") &&
                                Contains("v = 0"));
  // Sampled at the chart's ends (g_uu = 0 there to round-off): the same message, not "not positive definite".
  const KerrNewmanMetric kerr(1.0, 0.95, 0.0);
  SampledField ends = f;
  for (int j = 0; j < f.nv; ++j)
    for (int i = 0; i < f.nu; ++i) {
      const Eigen::Matrix2d g = kerr.g(f.nodeU(i), j * M_PI / (f.nv - 1));
      const size_t k = static_cast<size_t>(j) * f.nu + i;
      ends.guu[k] = g(0, 0), ends.guv[k] = g(0, 1), ends.gvv[k] = g(1, 1);
    }
  CHECK_THAT(fieldError(ends), Contains("is this a sphere? add `poles both`"));
  // A genuine annulus — the band 0.3 ≤ θ ≤ π − 0.3 of the same horizon — passes.
  SampledField band = f;
  for (int j = 0; j < f.nv; ++j)
    for (int i = 0; i < f.nu; ++i) {
      const Eigen::Matrix2d g = kerr.g(f.nodeU(i), 0.3 + j * (M_PI - 0.6) / (f.nv - 1));
      const size_t k = static_cast<size_t>(j) * f.nu + i;
      band.guu[k] = g(0, 0), band.guv[k] = g(0, 1), band.gvv[k] = g(1, 1);
    }
  band.domain.v0 = 0.3, band.domain.v1 = M_PI - 0.3;
  CHECK(fieldError(band).empty());
}

TEST_CASE("field checks: g_uu and g_vv swapped on a pole-to-pole chart name the convention u = phi, v = theta") {
  SampledField f = kerrField();
  std::swap(f.guu, f.gvv);
  CHECK_THAT(fieldError(f), Contains("u must be phi") && Contains("v theta") && Contains("swapped"));
  CHECK(fieldError(kerrField()).empty());
}

TEST_CASE("field checks: a transposed grid is named as such") {
  // Pole-to-pole: the Kerr data written v fastest.
  const SampledField good = kerrField();
  SampledField t = good;
  for (int i = 0; i < good.nu; ++i)
    for (int j = 0; j < good.nv; ++j) {
      const size_t from = static_cast<size_t>(j) * good.nu + i, to = static_cast<size_t>(i) * good.nv + j;
      t.guu[to] = good.guu[from], t.guv[to] = good.guv[from], t.gvv[to] = good.gvv[from];
    }
  CHECK_THAT(fieldError(t), Contains("transposed"));
  // A rectangle chart (no poles) whose metric depends on u and v: the roughness test. (A metric of one variable on a
  // periodic axis — a torus of revolution — reads as smoothly either way; only square grids are never tested.)
  SampledField rect;
  rect.source = "rect.txt";
  rect.domain.u0 = 0, rect.domain.u1 = 1, rect.domain.v0 = 0, rect.domain.v1 = 1;
  rect.nu = 40, rect.nv = 20;
  for (int j = 0; j < rect.nv; ++j)
    for (int i = 0; i < rect.nu; ++i) {
      const double u = rect.nodeU(i), v = rect.nodeV(j);
      rect.guu.push_back(1 + u + v * v), rect.guv.push_back(0.1 * u * v), rect.gvv.push_back(2 + 0.5 * std::sin(3 * u) + v);
    }
  CHECK(fieldError(rect).empty());
  SampledField rt = rect;
  for (int i = 0; i < rect.nu; ++i)
    for (int j = 0; j < rect.nv; ++j) {
      const size_t from = static_cast<size_t>(j) * rect.nu + i, to = static_cast<size_t>(i) * rect.nv + j;
      rt.guu[to] = rect.guu[from], rt.guv[to] = rect.guv[from], rt.gvv[to] = rect.gvv[from];
    }
  CHECK_THAT(fieldError(rt), Contains("rect.txt: the samples look transposed"));
}

TEST_CASE("field check report: topology, area 8 pi M r+, integral of K = 4 pi, smallest det g") {
  const FieldCheckReport r = checkField(kerrField());
  const double rp = 1 + std::sqrt(1 - 0.95 * 0.95);
  CHECK(r.shape == "sphere");
  CHECK(r.eulerCharacteristic == 2);
  CHECK(r.boundaryLoops == 0);
  // The spline interpolant's area and curvature against the closed forms, to the 64 × 32 sampling's accuracy: the
  // area is fourth order in h = π/32 (bound 1e-6 relative); ∫K dA is 4π by Gauss–Bonnet up to the interpolant's cone
  // defect at the poles, where g_uu/sin²v and g_vv agree only to O(h²) (measured 3.2e-7 relative; bound 1e-6).
  CHECK(r.area == Approx(8 * M_PI * rp).epsilon(1e-6));
  CHECK(r.totalCurvature == Approx(4 * M_PI).epsilon(1e-6));
  CHECK(r.gaussBonnet == Approx(4 * M_PI).epsilon(1e-15));
  CHECK((r.minDetNodeV == 0 || r.minDetNodeV == 31));  // det g = g_φφ g_θθ is smallest next to a pole
  CHECK(r.minDetG > 0);
  CHECK(r.minDetRegular > 0);
}
