// test_uniformized_metric_reuse.cpp — remeshUniformized on a UniformizedMetric that has already been used (metric_remesh.h:
// `conformesh convergence` prepares one uniformization and refines it at several ε) gives the same output, bit for
// bit, as remeshMetric with a fresh uniformization: the prepared stages carry no state from one refinement into the
// next. Both the sphere-chart path (uniformize to the sphere) and the kept-boundary path (a Bézier patch) are run.
//
// "Bit for bit" relies on every stage being deterministic for fixed input and options: the flow's two-thread split
// is fixed (docs/ricci_flow.md), so each comparison below is exact (==), not within a tolerance.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

namespace {

// Number of entries where a and b differ (exact comparison; 0 when identical), or −1 when the sizes differ.
template <class T>
long differences(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return -1;
  long n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += !(a[i] == b[i]);
  return n;
}

void requireIdentical(const RemeshResult& a, const RemeshResult& b) {
  REQUIRE(a.mesh.mesh.nVertices() == b.mesh.mesh.nVertices());
  REQUIRE(a.mesh.mesh.nHalfedges() == b.mesh.mesh.nHalfedges());
  std::vector<int> tailsA, tailsB, edgesA, edgesB;
  for (int h = 0; h < a.mesh.mesh.nHalfedges(); ++h) {
    tailsA.push_back(a.mesh.mesh.tail(h));
    tailsB.push_back(b.mesh.mesh.tail(h));
    edgesA.push_back(a.mesh.mesh.edge(h));
    edgesB.push_back(b.mesh.mesh.edge(h));
  }
  CHECK(differences(tailsA, tailsB) == 0);
  CHECK(differences(edgesA, edgesB) == 0);
  CHECK(differences(a.mesh.edgeLengths, b.mesh.edgeLengths) == 0);
  CHECK(differences(a.chart, b.chart) == 0);
  CHECK(differences(a.reference, b.reference) == 0);
  CHECK(differences(a.positions, b.positions) == 0);
  CHECK(differences(a.lambda, b.lambda) == 0);
  CHECK(differences(a.t0Face, b.t0Face) == 0);
  CHECK(differences(a.t0Bary, b.t0Bary) == 0);
  CHECK(a.invertedTriangles == b.invertedTriangles);
  CHECK(a.refinement.circumcenterInsertions == b.refinement.circumcenterInsertions);
  CHECK(a.refinement.boundarySplits == b.refinement.boundarySplits);
  CHECK(a.refinement.flips == b.refinement.flips);
  CHECK(a.quality.minAngleDeg == b.quality.minAngleDeg);
  CHECK(a.quality.meanCircumradius == b.quality.meanCircumradius);
}

}  // namespace

TEST_CASE("a reused UniformizedMetric refines exactly as a fresh uniformization does") {
  struct Case {
    std::unique_ptr<SmoothMetric> metric;
    double eps1, eps2;
    DiskTarget expected;
  };
  std::vector<Case> cases;
  cases.push_back({makeMetric("ellipsoid", {{"f", 0.3}}), 0.08, 0.05, DiskTarget::Circle});
  cases.push_back({makeMetric("teapot-patch", {{"patch", 4.0}}), 0.06, 0.04, DiskTarget::KeepBoundary});
  for (const Case& c : cases) {
    const SmoothMetric& m = *c.metric;
    SECTION(m.description()) {
      RemeshOptions o;
      o.t0Resolution = 10;
      o.epsilon = c.eps1;
      const UniformizedMetric prepared = uniformizeMetric(m, o);
      REQUIRE(prepared.diskTarget == c.expected);
      // Use it at ε1, then at another ε2, then at ε1 again; a fresh pipeline at ε1 must match both ε1 runs.
      const RemeshResult first = remeshUniformized(prepared, m, o);
      RemeshOptions o2 = o;
      o2.epsilon = c.eps2;
      const RemeshResult other = remeshUniformized(prepared, m, o2);
      const RemeshResult again = remeshUniformized(prepared, m, o);
      const RemeshResult fresh = remeshMetric(m, o);
      INFO(first.mesh.mesh.nVertices() << " vertices at eps " << c.eps1 << ", " << other.mesh.mesh.nVertices()
                                       << " at eps " << c.eps2);
      // The ε2 run is a different mesh (the comparisons below are not vacuous).
      REQUIRE(other.mesh.mesh.nVertices() > first.mesh.mesh.nVertices());
      requireIdentical(first, fresh);
      requireIdentical(again, fresh);
      // The prepared stages themselves: a second uniformizeMetric gives the same T0* and λ.
      const UniformizedMetric second = uniformizeMetric(m, o);
      CHECK(differences(prepared.uniformization.lambda, second.uniformization.lambda) == 0);
      CHECK(differences(prepared.uniformization.uniform.edgeLengths, second.uniformization.uniform.edgeLengths) == 0);
      CHECK(differences(prepared.t0.edgeLengths, second.t0.edgeLengths) == 0);
    }
  }
}
