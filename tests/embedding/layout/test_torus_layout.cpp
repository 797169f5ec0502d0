// test_torus_layout.cpp — periods and modulus of flat tori: a flat torus of a given skewed lattice gives back its τ
// to 1e-10 whichever basis it was built from; the uniformized torus of revolution (R, r), discretized from the `torus`
// metric family at four resolutions, converges to the exact modulus i·r/√(R² − r²) (reduced: i·max(a, 1/a)) at the
// order of a log–log fit; the modular reduction itself against hand-reduced values.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "conformesh/embedding/layout/torus_layout.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/flow/uniformization.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

TEST_CASE("the modular reduction lands in the standard fundamental domain with an SL(2,Z) matrix") {
  // τ = 2.3 + 0.5i: minus 2 → 0.3 + 0.5i; |τ|² = 0.34 < 1 → −1/τ = (−0.3 + 0.5i)/0.34 = −0.88 + 1.47i; plus 1 →
  // (0.04 + 0.5i)/0.34, in F.
  const ModularReduction r = reduceModulus({2.3, 0.5});
  CHECK(std::abs(r.tau - Complex(0.04, 0.5) / 0.34) < 1e-14);
  const auto [a, b, c, d] = r.matrix;
  CHECK(a * d - b * c == 1);
  const Complex tau0(2.3, 0.5);
  CHECK(std::abs((double(a) * tau0 + double(b)) / (double(c) * tau0 + double(d)) - r.tau) < 1e-14);
  CHECK(std::abs(reduceModulus({0.2, 3.0}).tau - Complex(0.2, 3.0)) == 0);  // already reduced: untouched
  CHECK_THROWS_WITH(reduceModulus({0.5, -1.0}), Catch::Contains("Im tau > 0"));
}

TEST_CASE("a flat torus of a skewed lattice gives back its modulus to 1e-10") {
  // Lattice ω₁ = 2 e^{0.4i}, ω₂ = ω₁ (0.3 + 1.1i): τ = 0.3 + 1.1i is already in F (|Re| ≤ ½, |τ| = 1.14 ≥ 1). Built
  // from the reduced basis and from the skewed basis (ω₁, ω₂ + 2ω₁), which has the same lattice.
  const Complex w1 = std::polar(2.0, 0.4), tau(0.3, 1.1), w2 = w1 * tau;
  for (bool reduce : {true, false}) {
    FlatTorusOptions o;
    o.omega1 = w1;
    o.omega2 = w2 + 2.0 * w1;
    o.n = 12;
    o.reduceBasis = reduce;
    const TorusLayout t = layoutTorus(toTriangulation(makeFlatTorus(o)));
    INFO("reduce " << reduce << ": tau " << t.tau << ", omega " << t.omega1 << " " << t.omega2);
    CHECK(std::abs(t.tau - tau) < 1e-10);
    CHECK(t.maxRotation < 1e-12);
    // The periods span the lattice: |ω₁ × ω₂| is the torus area |Im(ω̄₁ω₂)|.
    CHECK(std::abs(std::imag(std::conj(t.omega1) * t.omega2)) == Approx(std::imag(std::conj(w1) * w2)).epsilon(1e-12));
    CHECK(t.domain.minSignedArea > 0);
    CHECK(t.domain.maxVertexResidual < 1e-12);
    CHECK(t.domain.relationResidual < 1e-12);
  }
}

TEST_CASE("a flat torus with one edge lengthened is detected by its holonomy") {
  // Control: 1e-6 relative on one edge makes the angle sums of its quad's vertices miss 2π by ~1e-6: the per-vertex
  // relations must show it (the generators' holonomy, a global quantity, sees a local change only at second order).
  FlatTorusOptions o;
  o.omega2 = {0.3, 1.1};
  o.n = 8;
  IntrinsicTriangulation tri = toTriangulation(makeFlatTorus(o));
  tri.edgeLengths[5] *= 1 + 1e-6;
  const TorusLayout t = layoutTorus(tri);
  INFO("vertex residual " << t.domain.maxVertexResidual << ", max rotation " << t.maxRotation);
  CHECK(t.domain.maxVertexResidual > 1e-7);
}

TEST_CASE("a torus of revolution converges to the rectangular modulus i r/sqrt(R^2 - r^2)") {
  const double R = 1.0, r = 0.4, ratio = r / std::sqrt(R * R - r * r);
  const Complex exact(0, std::max(ratio, 1 / ratio));  // in F: the period ratio ≥ 1, Re 0
  const auto metric = makeMetric("torus", {{"R", R}, {"r", r}});
  std::vector<double> hs, errors;
  for (int n : {6, 12, 24, 48}) {
    DiscretizationOptions d;
    d.resolution = n;
    const IntrinsicTriangulation input = toTriangulation(discretizeMetric(*metric, d));
    const Uniformization u = uniformize(input);
    const TorusLayout t = layoutTorus(u.uniform);
    CHECK(t.domain.minSignedArea > 0);
    CHECK(t.domain.relationResidual < 1e-9);
    double h = 0;
    for (double l : input.edgeLengths) h += l;
    hs.push_back(h / input.edgeLengths.size());
    errors.push_back(std::abs(t.tau - exact));
  }
  const double order = fitLogLogSlope(hs, errors);
  INFO("modulus errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3] << ", order "
                         << order);
  CHECK(order > 1.8);
  CHECK(errors.back() < errors.front() / 30);
  WARN("torus of revolution: modulus errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3]
                                              << ", order " << order);
}

TEST_CASE("layoutTorus rejects what is not a flat torus") {
  const IntrinsicTriangulation sphere = toTriangulation(makeIcosphere({1, 1.0}));
  CHECK_THROWS_WITH(layoutTorus(sphere), Catch::Contains("genus 0"));
  GenusSurfaceOptions g;
  g.genus = 2;
  g.resolution = 1;
  CHECK_THROWS_WITH(layoutTorus(toTriangulation(makeGenusSurface(g))), Catch::Contains("genus 2"));
  CHECK_THROWS_WITH(layoutTorus(toTriangulation(makeDisk({2, 1.0}))), Catch::Contains("boundary loop"));
}
