// make_seeds.cpp — writes the small seed corpus the reader fuzzers start from (run_fuzzers.sh calls it): valid and
// nearly valid OBJ, OFF and PLY files exercising every feature the readers know (corner forms, negative indices,
// polygons, OFF prefixes, every PLY encoding and scalar type, skipped lists, metric-only meshes with edge_index), so
// that the fuzzer mutates meaningful structure instead of discovering the keywords by chance.
//
// Usage: make_seeds OUTDIR   (creates OUTDIR/obj, OUTDIR/off, OUTDIR/ply)
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "io/mesh_io_internal.h"

using namespace conformesh::intrinsic;
namespace fs = std::filesystem;

namespace {

void put(const fs::path& dir, const std::string& name, const std::string& bytes) {
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
}

MeshData octahedron() {
  MeshData d;
  d.nVertices = 6;
  d.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1.5}};
  d.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  d.vertexProperties["lambda"] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  d.comments = {"octahedron"};
  return d;
}

MeshData torusDeltaComplex() {
  MeshData d;
  d.nVertices = 1;
  d.faces = {{0, 0, 0}, {0, 0, 0}};
  d.edges = {{0, 0, 1.0}, {0, 0, 1.25}, {0, 0, 1.5}};
  d.cornerEdges = {{0, 1, 2}, {0, 2, 1}};
  d.edgeProperties["weight"] = {1, 2, 3};
  d.background = Background::Hyperbolic;
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_seeds OUTDIR\n");
    return 2;
  }
  const fs::path out = argv[1];
  const MeshData oct = octahedron();
  const MeshData torus = torusDeltaComplex();

  put(out / "obj", "octahedron.obj", detail::serializeObj(oct));
  put(out / "obj", "features.obj",
      "# geometry spherical\nmtllib a.mtl\no x\nv 0 0 0\nv 1 0 0 1\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "g g\ns 1\nusemtl m\nf 1/1/1 2//1 3/1 4\nf -4 -2 -1\nl 1 2\n");
  put(out / "obj", "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 0\n");

  put(out / "off", "octahedron.off", detail::serializeOff(oct));
  put(out / "off", "coff.off",
      "COFF\n# comment\n4 2 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n1 1 0 0 0 1 1\n0 1 0 1 1 1 1\n4 0 1 2 3 255 0 0\n"
      "3 0 2 3\n");
  put(out / "off", "noff.off", "NOFF 3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");

  for (const PlyEncoding enc : {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    const std::string tag = enc == PlyEncoding::Ascii ? "ascii" : enc == PlyEncoding::BinaryLittleEndian ? "le" : "be";
    put(out / "ply", "octahedron_" + tag + ".ply", detail::serializePly(oct, enc));
    put(out / "ply", "torus_" + tag + ".ply", detail::serializePly(torus, enc));
  }
  put(out / "ply", "skip_ascii.ply",
      "ply\nformat ascii 1.0\ncomment geometry euclidean\nobj_info x\nelement material 1\n"
      "property list ushort float kd\nelement vertex 3\nproperty char a\nproperty uchar b\nproperty short c\n"
      "property ushort d\nproperty int e\nproperty uint f\nproperty float x\nproperty double y\nproperty float32 z\n"
      "property list uint8 int16 junk\nelement face 1\nproperty list uint8 uint32 vertex_index\nproperty int8 flags\n"
      "element edge 3\nproperty int32 vertex1\nproperty uint16 vertex2\nproperty float64 length\n"
      "end_header\n2 0.5 0.25\n-1 2 -3 4 -5 6 0 0 0 0\n1 1 1 1 1 1 1 0 0 1 7\n2 2 2 2 2 2 0 1 0 2 1 2\n3 0 1 2 -1\n"
      "0 1 1\n1 2 1.4142135623730951\n2 0 1\n");
  return 0;
}
