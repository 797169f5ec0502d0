// test_disk_double.cpp — the double of a disk (intrinsic/src/flow/disk_double.h): its combinatorics (closed, genus 0,
// V = 2V − V_∂, every edge interior, mirror an involution fixing the boundary), and its uniformization to the unit
// sphere by the closed genus-0 route: reflection symmetry of the solution (mirror vertices' λ agree, the boundary on a
// great circle) on a regular fan, whose circle domain is known (the centre at the pole, the boundary the equator at
// equal angles), and on CGAL's blob.off, whose circle-domain flow fails; what the flips do to the two halves.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "flow/disk_double.h"
#include "support/gauss_bonnet_bound.h"

using namespace conformesh::intrinsic;
using conformesh::intrinsic::detail::DiskDouble;
using conformesh::intrinsic::detail::DiskHalf;
using conformesh::intrinsic::detail::doubleDisk;
using conformesh::intrinsic::detail::halveDoubleSphere;

namespace {

std::string dataFile(const std::string& name) {
  return std::string(CONFORMESH_TEST_DATA_DIR) + "/" + name;
}

void checkDoubleCombinatorics(const IntrinsicTriangulation& disk, const DiskDouble& d) {
  int boundary = 0;
  for (int v = 0; v < disk.mesh.nVertices(); ++v) boundary += disk.mesh.isBoundaryVertex(v);
  const HalfedgeMesh& m = d.surface.mesh;
  CHECK(m.nVertices() == 2 * disk.mesh.nVertices() - boundary);
  CHECK(m.nFaces() == 2 * disk.mesh.nFaces());
  CHECK(m.eulerCharacteristic() == 2);
  for (int e = 0; e < m.nEdges(); ++e) CHECK_FALSE(m.isBoundaryEdge(e));
  for (int v = 0; v < m.nVertices(); ++v) {
    CHECK(d.mirror[d.mirror[v]] == v);
    CHECK((d.mirror[v] == v) == (v < disk.mesh.nVertices() && disk.mesh.isBoundaryVertex(v)));
  }
}

// The double's sphere: how symmetric under the mirror (λ, and the boundary's distance from the great circle normal to
// the centre of mass difference of the two halves), and how many final edges join the two halves' interiors.
struct Symmetry {
  double lambda = 0, greatCircle = 0;
  int crossing = 0;
};

Symmetry measureSymmetry(const DiskDouble& d, const Uniformization& s, int diskVertices) {
  Symmetry out;
  const HalfedgeMesh& m = s.uniform.mesh;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int v = 0; v < m.nVertices(); ++v) {
    out.lambda = std::max(out.lambda, std::abs(s.lambda[v] - s.lambda[d.mirror[v]]));
    if (v < diskVertices) normal += s.positions[v] - s.positions[d.mirror[v]];
  }
  normal.normalize();
  for (int v = 0; v < diskVertices; ++v)
    if (d.mirror[v] == v) out.greatCircle = std::max(out.greatCircle, std::abs(s.positions[v].dot(normal)));
  auto side = [&](int v) { return d.mirror[v] == v ? 0 : (v < diskVertices ? 1 : -1); };
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    if (side(m.tail(h)) * side(m.tip(h)) < 0) ++out.crossing;
  }
  return out;
}

}  // namespace

TEST_CASE("the double of a regular fan is a symmetric bipyramid: the boundary on the equator at equal angles") {
  // makeDisk with one ring: the centre and the regular hexagon, its own circle domain (centre 0, vertices at the
  // sixth roots of unity up to rotation). The double is the regular hexagonal bipyramid; on the unit sphere, centred,
  // the poles are the two centres and the hexagon the equator at equal angles.
  const IntrinsicTriangulation fan = toTriangulation(makeDisk({1, 1.0}));
  const DiskDouble d = doubleDisk(fan);
  checkDoubleCombinatorics(fan, d);
  const Uniformization s = uniformize(d.surface);
  const Symmetry sym = measureSymmetry(d, s, fan.mesh.nVertices());
  CHECK(sym.lambda < 1e-10);
  CHECK(sym.greatCircle < 1e-10);
  CHECK(sym.crossing == 0);
  int centre = 0;
  for (int v = 0; v < fan.mesh.nVertices(); ++v)
    if (!fan.mesh.isBoundaryVertex(v)) centre = v;
  CHECK(s.positions[centre].dot(s.positions[d.mirror[centre]]) == Approx(-1).epsilon(1e-10));
  for (int v = 0; v < fan.mesh.nVertices(); ++v)
    if (v != centre) CHECK(std::abs(s.positions[v].dot(s.positions[centre])) < 1e-10);
}

TEST_CASE("the doubles of CGAL's disks whose circle-domain flow fails are uniformized, mirror-symmetric") {
  // blob.off ends at a degenerate face next to a boundary edge, corner_tris_with_hole.off and corner_with_hole.off
  // stall (1.2e-6, 1.2e-8 rad), ALSTOM_TEST4.off's component 0 hits the step cap (1.2e-4 rad). The double has no
  // boundary edge: the sphere's uniqueness up to Möbius maps, with the centring's mirror-symmetric weights, makes the
  // solution symmetric up to a rotation, so mirror vertices have one λ and the boundary lies on a great circle.
  for (const char* file : {"blob.off", "corner_tris_with_hole.off", "corner_with_hole.off", "ALSTOM_TEST4.off"}) {
    CAPTURE(file);
    const IntrinsicTriangulation disk = splitComponents(toTriangulation(readMesh(dataFile(file))))[0].triangulation;
    const DiskDouble d = doubleDisk(disk);
    checkDoubleCombinatorics(disk, d);
    const auto start = std::chrono::steady_clock::now();
    const Uniformization s = uniformize(d.surface);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Symmetry sym = measureSymmetry(d, s, disk.mesh.nVertices());
    std::printf(
        "%s double (%d vertices): %d Newton steps, %lld flips, residual %.3g, %.3f s; mirror |dlambda| %.3g, "
        "boundary off the great circle %.3g, edges joining the halves' interiors %d of %d\n",
        file, s.uniform.mesh.nVertices(), s.report.newtonSteps, static_cast<long long>(s.report.flips),
        s.report.maxResidual, seconds, sym.lambda, sym.greatCircle, sym.crossing, s.uniform.mesh.nEdges());
    CHECK(s.report.maxResidual < 1e-10);
    CHECK(sym.lambda < 1e-8);
    CHECK(sym.greatCircle < 1e-8);
    // Stereographic projection from the mirror pole: z = x⊥/(1 + x·n), the boundary onto |z| = 1. The disk's own
    // faces, straight-line at z: measured how many fold (docs/ricci_flow.md §3.3, "The double").
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int v = 0; v < disk.mesh.nVertices(); ++v) n += s.positions[v] - s.positions[d.mirror[v]];
    n.normalize();
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    std::vector<Eigen::Vector2d> z(disk.mesh.nVertices());
    for (int v = 0; v < disk.mesh.nVertices(); ++v) {
      const Eigen::Vector3d& x = s.positions[v];
      z[v] = Eigen::Vector2d(x.dot(e1), x.dot(e2)) / (1 + x.dot(n));
    }
    int positive = 0, negative = 0;
    for (int f = 0; f < disk.mesh.nFaces(); ++f) {
      const Eigen::Vector2d a = z[disk.mesh.faceVertex(f, 0)], b = z[disk.mesh.faceVertex(f, 1)],
                            c = z[disk.mesh.faceVertex(f, 2)];
      const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      (area > 0 ? positive : negative) += 1;
    }
    std::printf("  disk faces straight-line at the projected points: %d positive, %d negative\n", positive, negative);
  }
}

namespace {

// The half's invariants as a circle domain, from its own lengths and positions (docs/ricci_flow.md §3.3): boundary
// vertices on the unit circle, interior angle sums 2π, each boundary angle sum the inscribed polygon's
// π − (φ_prev + φ_next), φ = asin(ℓ/2), Gauss–Bonnet to round-off, every face a Euclidean triangle, and every length
// the straight distance of the written positions (a straight-line triangulation, kept by its Lawson flips).
void checkHalfIsCircleDomain(const IntrinsicTriangulation& t, const std::vector<Eigen::Vector3d>& z) {
  const HalfedgeMesh& m = t.mesh;
  REQUIRE(m.components().size() == 1);
  CHECK(m.components()[0].genus == 0);
  const std::vector<std::vector<int>> loops = m.boundaryLoops();
  REQUIRE(loops.size() == 1);
  const std::vector<int>& loop = loops[0];
  const int k = static_cast<int>(loop.size());
  const std::vector<double> sums = angleSums(t);
  double circle = 0, interior = 0, boundary = 0, straight = 0;
  for (int v = 0; v < m.nVertices(); ++v)
    if (m.isBoundaryVertex(v))
      circle = std::max(circle, std::abs(z[v].norm() - 1));
    else
      interior = std::max(interior, std::abs(sums[v] - 2 * M_PI));
  for (int i = 0; i < k; ++i) {
    const double into = t.length(loop[(i + k - 1) % k]), out = t.length(loop[i]);
    boundary = std::max(boundary, std::abs(sums[m.tail(loop[i])] - (M_PI - std::asin(into / 2) - std::asin(out / 2))));
  }
  int violating = 0;
  for (int f = 0; f < m.nFaces(); ++f) {
    const double a = t.length(HalfedgeMesh::halfedge(f, 0)), b = t.length(HalfedgeMesh::halfedge(f, 1)),
                 c = t.length(HalfedgeMesh::halfedge(f, 2));
    violating += !(a < b + c && b < c + a && c < a + b);
  }
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    straight = std::max(straight, std::abs(t.edgeLengths[e] - (z[m.tip(h)] - z[m.tail(h)]).norm()));
  }
  const double gaussBonnet = curvatureTotals(t).gaussBonnetResidual;
  std::printf(
      "  %d vertices, %d faces, %d on the loop; unit circle to %.3g, interior angle sums to %.3g, boundary angle sums "
      "to %.3g, lengths straight to %.3g, Gauss-Bonnet %.3g\n",
      m.nVertices(), m.nFaces(), k, circle, interior, boundary, straight, gaussBonnet);
  CHECK(circle < 1e-10);
  CHECK(interior < 1e-10);
  CHECK(boundary < 1e-10);
  CHECK(straight < 1e-12);
  CHECK(violating == 0);
  CHECK(std::abs(gaussBonnet) < conformesh::testing::gaussBonnetRoundoff(m.nFaces()));
}

}  // namespace

TEST_CASE(
    "the half of the double is a circle domain with a boundary vertex where each crossing edge meets the mirror") {
  // CGAL's three disks whose own circle-domain flow fails, and fails again from the double's start (blob.off,
  // corner_tris_with_hole.off, corner_with_hole.off: one boundary loop each despite the names; ChineseDragon-10kv.off
  // has two loops, an annulus, out of scope). The half of the double's sphere is checked as a circle domain, each new
  // vertex is mapped by the double's correspondence onto an input boundary edge, and the half's boundary loop visits,
  // between consecutive input boundary vertices a, b, exactly the new vertices on edge ab in increasing parameter.
  for (const char* file : {"blob.off", "corner_tris_with_hole.off", "corner_with_hole.off"}) {
    CAPTURE(file);
    const IntrinsicTriangulation disk = toTriangulation(readMesh(dataFile(file)));
    const DiskDouble d = doubleDisk(disk);
    const Uniformization s = uniformize(d.surface);
    const DiskHalf half = halveDoubleSphere(disk, d, s);
    const HalfedgeMesh& m = half.plane.mesh;
    const int n = disk.mesh.nVertices();
    std::printf("%s half: %d crossing edges (%d self-mirror), %d new boundary vertices, %d plane flips\n", file,
                half.crossingEdges, half.selfMirrorCrossings, static_cast<int>(half.inserted.size()),
                half.delaunayFlips);
    CHECK(half.crossingEdges > 0);
    REQUIRE(m.nVertices() == n + static_cast<int>(half.inserted.size()));
    for (int v = 0; v < n; ++v) CHECK(m.isBoundaryVertex(v) == disk.mesh.isBoundaryVertex(v));
    checkHalfIsCircleDomain(half.plane, half.positions);
    std::vector<std::vector<std::pair<double, int>>> onEdge(disk.mesh.nEdges());
    for (std::size_t i = 0; i < half.inserted.size(); ++i) {
      const auto& q = half.inserted[i];
      CHECK(q.vertex == n + static_cast<int>(i));  // appended after the input's vertices, in order
      CHECK(m.isBoundaryVertex(q.vertex));
      CHECK(std::abs(q.offEdge) < 1e-8);
      CHECK(q.parameter > 0);
      CHECK(q.parameter < 1);
      onEdge[q.inputEdge].emplace_back(q.parameter, q.vertex);
    }
    // The loop order. (Both loop lists are stored: a range-for over boundaryLoops()[0] would read a destroyed
    // temporary.)
    const std::vector<int> loop = m.boundaryLoops()[0], inputLoop = disk.mesh.boundaryLoops()[0];
    const int k = static_cast<int>(loop.size());
    int start = 0;
    while (m.tail(loop[start]) >= n) ++start;
    for (int i = 0; i < k;) {
      const int a = m.tail(loop[(start + i) % k]);
      std::vector<int> between;
      int j = i + 1;
      while (m.tail(loop[(start + j) % k]) >= n) between.push_back(m.tail(loop[(start + j++) % k]));
      const int b = m.tail(loop[(start + j) % k]);
      int edge = -1, tail = -1;
      for (const int h : inputLoop)
        if ((disk.mesh.tail(h) == a && disk.mesh.tip(h) == b) || (disk.mesh.tail(h) == b && disk.mesh.tip(h) == a)) {
          edge = disk.mesh.edge(h);
          tail = disk.mesh.tail(disk.mesh.edgeHalfedge(edge));
        }
      CAPTURE(a, b);
      REQUIRE(edge >= 0);
      std::vector<std::pair<double, int>> expected = onEdge[edge];
      std::sort(expected.begin(), expected.end());
      if (tail != a) std::reverse(expected.begin(), expected.end());
      REQUIRE(expected.size() == between.size());
      for (std::size_t t = 0; t < between.size(); ++t) CHECK(expected[t].second == between[t]);
      i = j;
    }
  }
}

TEST_CASE("uniformize returns the half of the double for CGAL's disks whose restart fails too") {
  // The public route (uniformization.h): the input's vertices are vertices 0..V−1 of T0*, the inserted ones appended
  // and listed in insertedVertices on input boundary edges; the correspondence is empty (it cannot carry them).
  for (const char* file : {"blob.off", "corner_tris_with_hole.off", "corner_with_hole.off"}) {
    CAPTURE(file);
    const IntrinsicTriangulation disk = toTriangulation(readMesh(dataFile(file)));
    UniformizationOptions options;
    options.flow.tolerance = 1e-10;
    const Uniformization u = uniformize(disk, options);
    const int n = disk.mesh.nVertices();
    std::printf("%s: uniformize gives %d inserted vertices, residual %.3g\n", file,
                static_cast<int>(u.insertedVertices.size()), u.report.maxResidual);
    CHECK(u.report.target == UniformizationTarget::CircleDomain);
    REQUIRE_FALSE(u.insertedVertices.empty());
    REQUIRE(u.uniform.mesh.nVertices() == n + static_cast<int>(u.insertedVertices.size()));
    CHECK(u.correspondence.nFaces() == 0);
    CHECK(u.report.maxResidual <= 1e-10);
    CHECK(u.report.effectiveTolerance == 1e-10);
    REQUIRE(u.positions.size() == static_cast<std::size_t>(u.uniform.mesh.nVertices()));
    REQUIRE(u.lambda.size() == u.positions.size());
    for (double l : u.lambda) CHECK(std::isfinite(l));
    for (std::size_t i = 0; i < u.insertedVertices.size(); ++i) {
      const auto& q = u.insertedVertices[i];
      CHECK(q.vertex == n + static_cast<int>(i));
      CHECK(disk.mesh.isBoundaryEdge(q.inputEdge));
    }
    // Vertex i of the input is vertex i of T0*: the input's interior vertices stay interior, its boundary boundary.
    for (int v = 0; v < n; ++v) CHECK(u.uniform.mesh.isBoundaryVertex(v) == disk.mesh.isBoundaryVertex(v));
    checkHalfIsCircleDomain(u.uniform, u.positions);
  }
}
