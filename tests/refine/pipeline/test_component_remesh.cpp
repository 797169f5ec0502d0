// test_component_remesh.cpp — remeshComponents on a mesh of two disjoint surfaces of different topology (a sphere
// and a torus, joined here), by both routes: each component remeshed to its own target (uniformized route: the
// sphere and the flat torus), Gauss–Bonnet 2πχ of each output component to round-off, each component's area kept
// (an exact retriangulation of its input), the merged file's area the sum of the components' and its input_face
// indices pointing into each component's own input faces.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <vector>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/refine/pipeline/component_remesh.h"

#include "support/gauss_bonnet_bound.h"
#include "support/test_meshes.h"

using namespace conformesh::intrinsic;
using namespace conformesh::refine;

namespace {

// A sphere (χ = 2) and a torus (χ = 0) side by side in one file's data, written out here.
MeshData sphereAndTorus() {
  TorusOptions torus;
  torus.n = 20;
  torus.m = 8;
  return conformesh::testing::joinByHand({makeIcosphere({2, 1.0}), makeTorus(torus)});
}

}  // namespace

TEST_CASE("remeshComponents: a sphere and a torus, each to its own target, areas and Gauss–Bonnet per component") {
  const MeshData data = sphereAndTorus();
  const IntrinsicTriangulation input = toTriangulation(data);
  MeshRemeshOptions o;
  o.epsilonRelative = 0.02;
  const RefineMetric route = GENERATE(RefineMetric::Uniformized, RefineMetric::Input);
  o.refineIn = route;
  INFO("route " << toString(route));
  const ComponentRemesh r = remeshComponents(input, data.positions, o);
  REQUIRE(r.parts.size() == 2);
  CHECK(r.epsilon == Approx(0.02 * std::sqrt(totalArea(input))).epsilon(1e-15));
  const int chi[] = {2, 0};
  const UniformizationTarget target[] = {UniformizationTarget::Sphere, UniformizationTarget::FlatTorus};
  double areaSum = 0;
  std::vector<MeshData> parts;
  for (int i = 0; i < 2; ++i) {
    const MeshRemeshResult& p = r.parts[i];
    INFO("component " << i);
    if (route == RefineMetric::Uniformized) CHECK(p.uniformization.target == target[i]);
    CHECK(p.mesh.mesh.nVertices() > r.components[i].triangulation.mesh.nVertices());
    const CurvatureTotals t = curvatureTotals(p.mesh);
    CHECK(t.eulerCharacteristic == chi[i]);
    CHECK(std::abs(t.gaussBonnetResidual) < conformesh::testing::gaussBonnetRoundoff(p.mesh.mesh.nFaces()));
    // An exact retriangulation of the component: VerificationTolerances::area's bound.
    CHECK(totalArea(p.mesh) == Approx(totalArea(r.components[i].triangulation)).epsilon(1e-9));
    areaSum += totalArea(p.mesh);
    parts.push_back(toMeshData(p, "two surfaces", r.epsilon));
  }
  CHECK(verifyComponentRemesh(r).passed());
  const MeshData merged = mergeComponentOutputs(r, parts);
  const IntrinsicTriangulation back = toTriangulation(merged);
  CHECK(back.mesh.components().size() == 2);
  CHECK(totalArea(back) == Approx(areaSum).epsilon(1e-12));
  CHECK(totalArea(back) == Approx(totalArea(input)).epsilon(1e-9));
  // Each output vertex's input face lies in its own component's faces of the input.
  const std::vector<double>& component = merged.vertexProperties.at("component");
  const std::vector<double>& face = merged.vertexProperties.at("input_face");
  for (int i = 0; i < 2; ++i) {
    const std::set<int> own(r.components[i].faces.begin(), r.components[i].faces.end());
    int outside = 0;
    for (std::size_t v = 0; v < component.size(); ++v)
      if (component[v] == i && !own.count(static_cast<int>(face[v]))) ++outside;
    CHECK(outside == 0);
  }
}
