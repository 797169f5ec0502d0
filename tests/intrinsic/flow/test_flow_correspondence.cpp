// test_flow_correspondence.cpp — the map T0* → T0 through vertex scaling and Ptolemy flips is a homeomorphism: it
// sends vertices to the same vertices exactly, points of a shared edge to one point from both sides, keeps small
// triangles positively oriented, is inverted by mapToUniform, and for a cocircular quad equals the Euclidean layout.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/flow/uniformization.h"

using namespace conformesh::intrinsic;

namespace {

Eigen::Vector3d positionOn(const MeshData& data, const HalfedgeMesh& mesh, const FacePoint& p) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) x += p.bary[k] * data.positions[mesh.faceVertex(p.face, k)];
  return x;
}

}  // namespace

TEST_CASE("a Ptolemy flip of a cocircular quad maps points like the Euclidean layout") {
  // Unit square a(0,0) b(1,1) c(0,1) d(1,0): faces (a,b,c), (b,a,d) share the diagonal ab; cocircular, so the Ptolemy
  // diagonal cd = √2 is the geometric one and the decorated-ideal correspondence must be the affine one.
  const std::vector<Eigen::Vector2d> P = {{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  IntrinsicTriangulation tri;
  tri.mesh = HalfedgeMesh::fromFaces({{0, 1, 2}, {1, 0, 3}}, 4);
  tri.edgeLengths.resize(tri.mesh.nEdges());
  for (int e = 0; e < tri.mesh.nEdges(); ++e) {
    const int h = tri.mesh.edgeHalfedge(e);
    tri.edgeLengths[e] = (P[tri.mesh.tail(h)] - P[tri.mesh.tip(h)]).norm();
  }
  const HalfedgeMesh before = tri.mesh;
  DiscreteConformalMetric metric(tri, Background::Euclidean);
  FlowCorrespondence log(2);
  int diagonal = -1;
  for (int e = 0; e < tri.mesh.nEdges(); ++e)
    if (!tri.mesh.isBoundaryEdge(e)) diagonal = e;
  REQUIRE(metric.flipPtolemy(diagonal, &log));
  CHECK(metric.referencePenner(diagonal) == Approx(std::sqrt(2.0)).epsilon(1e-15));
  log.logScale.assign(4, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<FacePoint> pts;
  for (int i = 0; i < 200; ++i) {
    double a = U(rng), b = U(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    pts.push_back({i % 2, {a, b, 1 - a - b}});
  }
  const std::vector<FacePoint> back = log.mapToInput(metric.mesh(), pts);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    Eigen::Vector2d x = Eigen::Vector2d::Zero(), y = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) {
      x += pts[i].bary[k] * P[metric.mesh().faceVertex(pts[i].face, k)];
      y += back[i].bary[k] * P[before.faceVertex(back[i].face, k)];
    }
    CHECK((x - y).norm() < 1e-14);
  }
}

TEST_CASE("the flow correspondence is a homeomorphism on uniformized real meshes") {
  for (const char* file : {"handle.off", "double-torus-example.off", "knot1.off", "patch-01.off"}) {
    SECTION(file) {
      const MeshData data = readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/" + file);
      const IntrinsicTriangulation input = toTriangulation(data);
      const Uniformization u = uniformize(input);
      const HalfedgeMesh& out = u.uniform.mesh;
      INFO(file << ": " << u.correspondence.flips().size() << " flips logged");
      CHECK(!u.correspondence.flips().empty());  // the maps below are exercised through flips
      double scale = 0;
      for (double l : input.edgeLengths) scale = std::max(scale, l);

      // Vertices to the same vertices.
      std::vector<FacePoint> corners;
      for (int f = 0; f < out.nFaces(); ++f)
        for (int k = 0; k < 3; ++k) {
          FacePoint p{f, {0, 0, 0}};
          p.bary[k] = 1;
          corners.push_back(p);
        }
      const std::vector<FacePoint> cornersBack = u.correspondence.mapToInput(out, corners);
      double worstVertex = 0;
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const int v = out.faceVertex(corners[i].face, static_cast<int>(i % 3));
        const Eigen::Vector3d x = positionOn(data, input.mesh, cornersBack[i]);
        worstVertex = std::max(worstVertex, (x - data.positions[v]).norm());
      }
      CHECK(worstVertex < 1e-12 * scale);

      // Continuity across every interior edge of T0*.
      std::vector<FacePoint> sideA, sideB;
      for (int h = 0; h < out.nHalfedges(); ++h) {
        const int t = out.twin(h);
        if (t == kInvalid || t < h) continue;
        for (double s : {0.3, 0.71}) {
          FacePoint a{HalfedgeMesh::face(h), {0, 0, 0}}, b{HalfedgeMesh::face(t), {0, 0, 0}};
          a.bary[h % 3] = 1 - s;                  // at tail(h)
          a.bary[HalfedgeMesh::next(h) % 3] = s;  // at tip(h)
          b.bary[t % 3] = s;                      // tail(t) = tip(h)
          b.bary[HalfedgeMesh::next(t) % 3] = 1 - s;
          sideA.push_back(a);
          sideB.push_back(b);
        }
      }
      const std::vector<FacePoint> backA = u.correspondence.mapToInput(out, sideA);
      const std::vector<FacePoint> backB = u.correspondence.mapToInput(out, sideB);
      double worstEdge = 0;
      for (std::size_t i = 0; i < backA.size(); ++i)
        worstEdge = std::max(worstEdge,
                             (positionOn(data, input.mesh, backA[i]) - positionOn(data, input.mesh, backB[i])).norm());
      CHECK(worstEdge < 1e-10 * scale);

      // Orientation: small counter-clockwise triangles around each face's centroid stay counter-clockwise.
      std::vector<FacePoint> small;
      const double d = 1e-3;
      for (int f = 0; f < out.nFaces(); ++f) {
        small.push_back({f, {1.0 / 3 + 2 * d, 1.0 / 3 - d, 1.0 / 3 - d}});
        small.push_back({f, {1.0 / 3 - d, 1.0 / 3 + 2 * d, 1.0 / 3 - d}});
        small.push_back({f, {1.0 / 3 - d, 1.0 / 3 - d, 1.0 / 3 + 2 * d}});
      }
      const std::vector<FacePoint> smallBack = u.correspondence.mapToInput(out, small);
      int checked = 0, negative = 0;
      for (std::size_t i = 0; i < smallBack.size(); i += 3) {
        const FacePoint &p = smallBack[i], &q = smallBack[i + 1], &r = smallBack[i + 2];
        if (p.face != q.face || p.face != r.face) continue;
        const double det =
            (q.bary[0] - p.bary[0]) * (r.bary[1] - p.bary[1]) - (q.bary[1] - p.bary[1]) * (r.bary[0] - p.bary[0]);
        ++checked;
        if (!(det > 0)) ++negative;
      }
      CHECK(checked > out.nFaces() / 2);
      CHECK(negative == 0);

      // mapToUniform inverts mapToInput (interior points: a point on an edge may come back in the other face).
      const std::vector<FacePoint> again = u.correspondence.mapToUniform(out, smallBack);
      double worstTrip = 0;
      for (std::size_t i = 0; i < again.size(); ++i) {
        REQUIRE(again[i].face == small[i].face);
        for (int k = 0; k < 3; ++k) worstTrip = std::max(worstTrip, std::abs(again[i].bary[k] - small[i].bary[k]));
      }
      CHECK(worstTrip < 1e-10);
    }
  }
}

TEST_CASE("the flow correspondence rejects points that are not on a face") {
  FlowCorrespondence log(2);
  HalfedgeMesh mesh = HalfedgeMesh::fromFaces({{0, 1, 2}, {1, 0, 3}}, 4);
  CHECK_THROWS_WITH(log.mapToInput(mesh, {{0, {0.5, 0.5, 0}}, {5, {1, 0, 0}}}),
                    Catch::Contains("point 1") && Catch::Contains("face 5"));
  CHECK_THROWS_WITH(log.mapToInput(mesh, {{1, {0.7, 0.7, -0.4}}}), Catch::Contains("point 0"));
}
