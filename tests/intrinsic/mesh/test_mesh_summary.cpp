// Tests for mesh_summary.h on real meshes made by others (CGAL's data set, Debian package libcgal-demo): genus,
// Euler characteristic, boundary loops as the meshes' makers describe them, and Gauss–Bonnet below 1e-9.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"

using namespace conformesh::intrinsic;

namespace {
struct Expected {
  const char* file;
  int genus, boundaryLoops, components;
};
}  // namespace

TEST_CASE("real meshes of genus 0-3 and with boundaries: topology and Gauss–Bonnet") {
  // Topology as the data set names it (double torus, 3-torus, ...); χ = 2 − 2g − b follows.
  const Expected cases[] = {{"cow.off", 0, 0, 1},         {"knot1.off", 1, 0, 1},
                            {"elk.off", 1, 0, 1},         {"eight.off", 2, 0, 1},
                            {"double-torus-example.off", 2, 0, 1}, {"elephant.off", 3, 0, 1},
                            {"3torus.off", 3, 0, 1},      {"patch-01.off", 0, 1, 1},
                            {"nefertiti.off", 0, 1, 1},   {"blade.off", 0, 2, 1},
                            {"mech-holes-shark.off", 0, 4, 1}};
  for (const Expected& c : cases) {
    const std::string path = std::string(CONFORMESH_TEST_DATA_DIR) + "/" + c.file;
    INFO(path);
    const IntrinsicTriangulation tri = toTriangulation(readMesh(path));
    const MeshSummary s = summarize(tri);
    CHECK(s.components.size() == static_cast<size_t>(c.components));
    CHECK(s.genus == c.genus);
    CHECK(s.boundaryLoops == c.boundaryLoops);
    CHECK(s.eulerCharacteristic == 2 - 2 * c.genus - c.boundaryLoops);
    CHECK(std::abs(s.curvature.gaussBonnetResidual) < 1e-9);
    CHECK(s.curvature.interiorDeficit + s.curvature.boundaryTurning ==
          Approx(2 * M_PI * s.eulerCharacteristic).margin(1e-9));
    CHECK(s.minCornerAngle > 0);
    CHECK(s.maxCornerAngle < M_PI);
    CHECK(s.nonDelaunayFraction >= 0);
    CHECK(s.nonDelaunayFraction <= 1);
  }
}

TEST_CASE("the smallest angle sum: the corner (1,0,0) of the reference tetrahedron, 45 + 45 + 60 deg") {
  // Vertices e2, e1, 0, e3 in the file: the origin has three right angles (270 deg); each e_i has two 45 deg corners of
  // its right isosceles faces and one 60 deg corner of the equilateral face, 150 deg = 5π/6.
  const MeshSummary s =
      summarize(toTriangulation(readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/reference_tetrahedron.off")));
  CHECK(s.minAngleSum == Approx(5 * M_PI / 6).margin(1e-12));
  CHECK(s.minAngleSumVertex >= 0);
  CHECK(s.minAngleSumVertex != 2);  // the file's vertex 2 is the origin
  CHECK(s.minAngleSumVertex <= 3);
}
