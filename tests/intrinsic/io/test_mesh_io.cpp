// test_mesh_io.cpp — the OBJ, OFF and PLY readers and writers (mesh_io.h).
//
// Round trips in every format and PLY encoding compare every double bit for bit (including subnormals, ±0 and the
// extremes of the range). Reader-only tests use hand-written text and hand-assembled binary bytes, so that a reader and
// writer wrong in the same way cannot pass. Each kind of bad input (missing/empty/truncated file, garbage, bad indices,
// negative and absurd counts, repeated vertices, non-finite numbers, non-positive lengths, inconsistent edge_index)
// must raise InputError whose message names the file, the line or element, and what was found. Real meshes from CGAL's
// data set, when the test data has been extracted, must all parse.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/io/mesh_io.h"

using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;
using conformesh::InputError;
namespace fs = std::filesystem;

namespace {

// === helpers

// A fresh directory per test program run; files are written into it by name. Removed when the program exits.
const fs::path& scratchDir() {
  struct Scratch {
    fs::path path = fs::temp_directory_path() / ("conformesh_test_mesh_io_" + std::to_string(::getpid()));
    Scratch() {
      fs::remove_all(path);
      fs::create_directories(path);
    }
    ~Scratch() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.path;
}

std::string writeFile(const std::string& name, const std::string& bytes) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError that `f` throws; fails the test if it throws nothing.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("expected an InputError, nothing was thrown");
  return {};
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Little-/big-endian byte assembly for hand-made binary PLY bodies, independent of the writer under test.
struct Bytes {
  bool bigEndian;
  std::string s;
  template <class T>
  Bytes& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    const std::uint16_t probe = 1;
    const bool hostLittle = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    if (bigEndian == hostLittle) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
    return *this;
  }
};

// Compares everything a format can carry, bit for bit.
void requireSameMesh(const MeshData& a, const MeshData& b, bool withLengthsAndProperties) {
  REQUIRE(a.nVertices == b.nVertices);
  REQUIRE(a.faces == b.faces);
  REQUIRE(a.background == b.background);
  REQUIRE(a.comments == b.comments);
  REQUIRE(a.positions.size() == b.positions.size());
  for (std::size_t v = 0; v < a.positions.size(); ++v)
    for (int k = 0; k < 3; ++k) REQUIRE(sameBits(a.positions[v][k], b.positions[v][k]));
  if (!withLengthsAndProperties) return;
  REQUIRE(a.cornerEdges == b.cornerEdges);
  REQUIRE(a.edges.size() == b.edges.size());
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    REQUIRE(a.edges[e].v0 == b.edges[e].v0);
    REQUIRE(a.edges[e].v1 == b.edges[e].v1);
    REQUIRE(sameBits(a.edges[e].length, b.edges[e].length));
  }
  for (const auto* props : {&a.vertexProperties, &a.edgeProperties}) {
    const auto& other = props == &a.vertexProperties ? b.vertexProperties : b.edgeProperties;
    REQUIRE(props->size() == other.size());
    for (const auto& [name, values] : *props) {
      INFO("property " << name);
      REQUIRE(other.count(name) == 1);
      const auto& w = other.at(name);
      REQUIRE(values.size() == w.size());
      for (std::size_t i = 0; i < values.size(); ++i) REQUIRE(sameBits(values[i], w[i]));
    }
  }
}

// Doubles that stress a text round trip: random mantissas over 600 decades, subnormals, ±0, the extremes.
std::vector<double> awkwardDoubles(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<double> x(n);
  for (double& d : x) d = std::ldexp(mantissa(rng), exponent(rng));
  const double specials[] = {0.0,
                             -0.0,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min() * 12345,
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max(),
                             0.1,
                             1.0 / 3.0};
  for (std::size_t i = 0; i < std::size(specials) && i < n; ++i) x[i] = specials[i];
  return x;
}

// An octahedron with awkward coordinates, every edge listed with a length, corner edge ids, per-vertex and per-edge
// properties, comments and a non-default background: everything the PLY writer can carry.
MeshData richOctahedron() {
  MeshData d;
  d.source = "octahedron";
  d.nVertices = 6;
  d.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const std::vector<double> c = awkwardDoubles(18, 1);
  for (int v = 0; v < 6; ++v) d.positions.emplace_back(c[3 * v], c[3 * v + 1], c[3 * v + 2]);
  std::map<std::pair<int, int>, int> edgeOf;
  const std::vector<double> lengths = awkwardDoubles(12, 2);
  for (const auto& f : d.faces) {
    std::array<int, 3> ce{};
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      const auto key = std::minmax(a, b);
      auto it = edgeOf.find(key);
      if (it == edgeOf.end()) {
        it = edgeOf.emplace(key, static_cast<int>(d.edges.size())).first;
        const double len = std::abs(lengths[d.edges.size()]);
        d.edges.push_back({a, b, len > 0 ? len : 0.75});
      }
      ce[k] = it->second;
    }
    d.cornerEdges.push_back(ce);
  }
  d.vertexProperties["u"] = awkwardDoubles(6, 3);
  d.vertexProperties["v"] = awkwardDoubles(6, 4);
  d.vertexProperties["lambda"] = awkwardDoubles(6, 5);
  d.vertexProperties["curvature"] = awkwardDoubles(6, 6);
  d.edgeProperties["weight"] = awkwardDoubles(12, 7);
  d.background = Background::Spherical;
  d.comments = {"made by test_mesh_io", "second comment: with punctuation, 1.5 and tabs\tinside"};
  return d;
}

// A one-vertex torus as a Δ-complex (the unit square glued along opposite sides, cut by a diagonal): two triangles
// with sides a, b, c, three self-loop edges; no positions at all.
MeshData oneVertexTorus() {
  MeshData d;
  d.source = "torus";
  d.nVertices = 1;
  d.faces = {{0, 0, 0}, {0, 0, 0}};
  d.edges = {{0, 0, 1.0}, {0, 0, 1.0}, {0, 0, std::sqrt(2.0)}};
  d.cornerEdges = {{0, 1, 2}, {0, 1, 2}};
  d.vertexProperties["lambda"] = {0.125};
  return d;
}

const PlyEncoding kEncodings[] = {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian};
const char* encodingName(PlyEncoding e) {
  return e == PlyEncoding::Ascii ? "ascii" : e == PlyEncoding::BinaryLittleEndian ? "binary LE" : "binary BE";
}

}  // namespace

// =====================================================================================================================
// Round trips
// =====================================================================================================================

TEST_CASE("PLY round trip keeps every field bit for bit in all three encodings", "[mesh_io][ply]") {
  const MeshData original = richOctahedron();
  for (const PlyEncoding enc : kEncodings) {
    INFO(encodingName(enc));
    const std::string path = (scratchDir() / ("rich.ply")).string();
    writeMesh(original, path, {enc});
    const MeshData back = readMesh(path);
    REQUIRE(back.source == path);
    REQUIRE(back.polygonsTriangulated == 0);
    requireSameMesh(original, back, true);
  }
}

TEST_CASE("metric-only Δ-complex with self-loops round-trips through PLY", "[mesh_io][ply]") {
  const MeshData original = oneVertexTorus();
  for (const PlyEncoding enc : kEncodings) {
    INFO(encodingName(enc));
    const std::string path = (scratchDir() / "torus.ply").string();
    writeMesh(original, path, {enc});
    const std::string text = readFile(path);
    REQUIRE(text.find("property double x") == std::string::npos);  // no positions written
    REQUIRE(text.find("property list uchar int edge_index") != std::string::npos);
    const MeshData back = readMesh(path);
    REQUIRE(back.positions.empty());
    requireSameMesh(original, back, true);
  }
}

TEST_CASE("a mesh with neither positions nor properties still round-trips (vertex element without properties)",
          "[mesh_io][ply]") {
  MeshData d = oneVertexTorus();
  d.vertexProperties.clear();
  for (const PlyEncoding enc : kEncodings) {
    const std::string path = (scratchDir() / "bare.ply").string();
    writeMesh(d, path, {enc});
    requireSameMesh(d, readMesh(path), true);
  }
}

TEST_CASE("OBJ and OFF round trips keep positions, faces, background and comments bit for bit", "[mesh_io][obj][off]") {
  const MeshData original = richOctahedron();
  for (const char* ext : {".obj", ".off", ".OBJ"}) {
    INFO(ext);
    const std::string path = (scratchDir() / (std::string("rich") + ext)).string();
    writeMesh(original, path);
    const MeshData back = readMesh(path);
    REQUIRE(back.edges.empty());
    REQUIRE(back.vertexProperties.empty());
    requireSameMesh(original, back, false);
  }
}

TEST_CASE("writing a metric-only mesh to OBJ or OFF is refused and points to PLY", "[mesh_io][obj][off]") {
  const MeshData d = oneVertexTorus();
  for (const char* name : {"metric.obj", "metric.off"}) {
    const std::string path = (scratchDir() / name).string();
    const std::string msg = errorOf([&] { writeMesh(d, path); });
    CHECK_THAT(msg, Contains(path) && Contains("metric-only") && Contains(".ply"));
    REQUIRE_FALSE(fs::exists(path));
  }
}

TEST_CASE("a failed write leaves the existing file untouched and no temporary behind", "[mesh_io]") {
  const std::string path = writeFile("keep.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string before = readFile(path);
  MeshData bad = richOctahedron();
  bad.faces[3][1] = 17;  // out of range
  const std::string msg = errorOf([&] { writeMesh(bad, path); });
  CHECK_THAT(msg, Contains(path) && Contains("face 3") && Contains("17"));
  REQUIRE(readFile(path) == before);
  for (const auto& entry : fs::directory_iterator(scratchDir()))
    REQUIRE(entry.path().filename().string().find(".tmp-") == std::string::npos);
  const std::string msg2 = errorOf([&] { writeMesh(richOctahedron(), "/nonexistent-dir/x.ply"); });
  CHECK_THAT(msg2, Contains("/nonexistent-dir/x.ply") && Contains("cannot write"));
}

// =====================================================================================================================
// Readers against hand-written input
// =====================================================================================================================

TEST_CASE("OBJ: corner forms, negative indices, polygons, ignored statements, comments", "[mesh_io][obj]") {
  const std::string text =
      "# a quad and a triangle\n"
      "mtllib m.mtl\no thing\ng group\ns off\nusemtl red\n"
      "v 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n"
      "vt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2//1 3/1 4\n"
      "v 0.5 0.5 1e-3\n"
      "f -5 -4 -1   # relative\n"
      "l 1 2\n"
      "# geometry hyperbolic\n";
  const MeshData d = parseObj(text, "t.obj");
  REQUIRE(d.nVertices == 5);
  REQUIRE(d.positions[2] == Eigen::Vector3d(1, 1, 0));
  REQUIRE(d.positions[4].z() == 1e-3);
  REQUIRE(d.faces == std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}});
  REQUIRE(d.polygonsTriangulated == 1);
  REQUIRE(d.background == Background::Hyperbolic);
  REQUIRE(d.comments == std::vector<std::string>{"a quad and a triangle", "relative"});
  // Faces may precede the vertices they name.
  REQUIRE(parseObj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "fwd.obj").faces.size() == 1);
}

TEST_CASE("OFF: prefixes with extra per-vertex data, face colours, comments, counts on the keyword line",
          "[mesh_io][off]") {
  const std::string coff =
      "COFF # coloured\n4 2 5\n"
      "0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n"
      "# interior comment\n"
      "0 1 0 1 1 1 1\n"
      "3 0 1 2 0.5 0.5 0.5\n3 0 2 3\n";
  const MeshData d = parseOff(coff, "c.off");
  REQUIRE(d.nVertices == 4);
  REQUIRE(d.positions[3] == Eigen::Vector3d(0, 1, 0));
  REQUIRE(d.faces == std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}});
  REQUIRE(d.comments == std::vector<std::string>{"coloured", "interior comment"});
  const MeshData n = parseOff("NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n4 0 1 2 1\n", "n.off");
  // "4 0 1 2 1": a quad whose fan triangle (0, 2, 1) is fine.
  REQUIRE(n.faces == std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 1}});
  REQUIRE(n.polygonsTriangulated == 1);
  const std::string msg = errorOf([] { parseOff("4OFF\n1 1 0\n0 0 0 0\n", "h.off"); });
  CHECK_THAT(msg, Contains("h.off:1:") && Contains("4-D"));
}

TEST_CASE("PLY: every scalar type and alias, in all three encodings", "[mesh_io][ply]") {
  // Vertex 0 and 1 carry the extremes of each type; the values are written by hand as text and as bytes.
  const char* types[] = {"char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
                         "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  const double v0[] = {-128,  255, -32768,     65535, -2147483648.0, 4294967295.0, 0.5, -0.1, 127, 0,
                       32767, 0,   2147483647, 0,     -1.5,          1e300};
  std::string header = "ply\nformat FMT 1.0\nelement vertex 1\n";
  for (int i = 0; i < 16; ++i) header += std::string("property ") + types[i] + " p" + std::to_string(i) + "\n";
  header += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const auto withFormat = [&](const char* fmt) {
    std::string h = header;
    h.replace(h.find("FMT"), 3, fmt);
    return h;
  };
  // Face (0, 0, 0) would repeat a vertex; use a 1-vertex mesh with faces checked separately: replace by 3 vertices.
  std::string ascii = withFormat("ascii");
  ascii.replace(ascii.find("vertex 1"), 8, "vertex 3");
  std::string asciiBody;
  for (int copy = 0; copy < 3; ++copy) {
    asciiBody += "-128 255 -32768 65535 -2147483648 4294967295 0.5 -0.1 127 0 32767 0 2147483647 0 -1.5 1e300\n";
  }
  asciiBody += "3 0 1 2\n";
  const MeshData a = parsePly(ascii + asciiBody, "types.ply");
  for (bool big : {false, true}) {
    Bytes b{big, {}};
    for (int copy = 0; copy < 3; ++copy) {
      b.put<std::int8_t>(-128).put<std::uint8_t>(255).put<std::int16_t>(-32768).put<std::uint16_t>(65535);
      b.put<std::int32_t>(INT32_MIN).put<std::uint32_t>(4294967295u).put<float>(0.5f).put<double>(-0.1);
      b.put<std::int8_t>(127).put<std::uint8_t>(0).put<std::int16_t>(32767).put<std::uint16_t>(0);
      b.put<std::int32_t>(INT32_MAX).put<std::uint32_t>(0).put<float>(-1.5f).put<double>(1e300);
    }
    b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    std::string h = withFormat(big ? "binary_big_endian" : "binary_little_endian");
    h.replace(h.find("vertex 1"), 8, "vertex 3");
    const MeshData m = parsePly(h + b.s, "types.ply");
    for (const MeshData* d : {&a, &m}) {
      REQUIRE(d->positions.empty());
      REQUIRE(d->vertexProperties.size() == 16);
      for (int i = 0; i < 16; ++i)
        for (int v = 0; v < 3; ++v) REQUIRE(d->vertexProperties.at("p" + std::to_string(i))[v] == v0[i]);
      REQUIRE(d->faces == std::vector<std::array<int, 3>>{{0, 1, 2}});
    }
  }
}

TEST_CASE("PLY: unknown elements and properties, lists included, are skipped in all three encodings",
          "[mesh_io][ply]") {
  const std::string header =
      "ply\nformat FMT 1.0\ncomment made by hand\nobj_info ignored\n"
      "element material 2\nproperty list ushort float kd\nproperty uchar id\n"
      "element vertex 3\nproperty float x\nproperty list uchar short junk\nproperty float y\nproperty float z\n"
      "property uchar red\n"
      "element face 1\nproperty list uchar float texcoord\nproperty list uint int vertex_index\nproperty int flags\n"
      "element extra 2\nproperty double a\nproperty short b\n"
      "end_header\n";
  const auto fmt = [&](const char* f) {
    std::string h = header;
    h.replace(h.find("FMT"), 3, f);
    return h;
  };
  const std::string body =
      "3 0.1 0.2 0.3 7\n0 9\n"
      "0 2 -1 -2 0 0 10\n1 0 0 0 20\n0 1 1 2 0 30\n"
      "2 0.5 0.5 3 0 1 2 -7\n"
      "1.5 2\n2.5 3\n";
  const MeshData a = parsePly(fmt("ascii") + body, "skip.ply");
  for (bool big : {false, true}) {
    Bytes b{big, {}};
    b.put<std::uint16_t>(3).put<float>(0.1f).put<float>(0.2f).put<float>(0.3f).put<std::uint8_t>(7);
    b.put<std::uint16_t>(0).put<std::uint8_t>(9);
    b.put<float>(0).put<std::uint8_t>(2).put<std::int16_t>(-1).put<std::int16_t>(-2).put<float>(0).put<float>(0);
    b.put<std::uint8_t>(10);
    b.put<float>(1).put<std::uint8_t>(0).put<float>(0).put<float>(0).put<std::uint8_t>(20);
    b.put<float>(0).put<std::uint8_t>(1).put<std::int16_t>(1).put<float>(2).put<float>(0).put<std::uint8_t>(30);
    b.put<std::uint8_t>(2).put<float>(0.5f).put<float>(0.5f);
    b.put<std::uint32_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2).put<std::int32_t>(-7);
    b.put<double>(1.5).put<std::int16_t>(2).put<double>(2.5).put<std::int16_t>(3);
    const MeshData m = parsePly(fmt(big ? "binary_big_endian" : "binary_little_endian") + b.s, "skip.ply");
    for (const MeshData* d : {&a, &m}) {
      REQUIRE(d->nVertices == 3);
      REQUIRE(d->positions == std::vector<Eigen::Vector3d>{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}});
      REQUIRE(d->vertexProperties.size() == 1);
      REQUIRE(d->vertexProperties.at("red") == std::vector<double>{10, 20, 30});
      REQUIRE(d->faces == std::vector<std::array<int, 3>>{{0, 1, 2}});
      REQUIRE(d->comments == std::vector<std::string>{"made by hand"});
    }
  }
}

TEST_CASE("PLY: metric-only file as documented in docs/formats.md", "[mesh_io][ply]") {
  // A unit right isosceles triangle split... here: a tetrahedron with all six lengths 1 (regular) and one extra
  // vertex property, with the edge element before the face element (any order is allowed).
  const std::string text =
      "ply\nformat ascii 1.0\ncomment geometry euclidean\ncomment regular tetrahedron\n"
      "element vertex 4\nproperty double curvature\n"
      "element edge 6\nproperty int vertex1\nproperty int vertex2\nproperty double length\nproperty double stress\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "3.14159\n3.14159\n3.14159\n3.14159\n"
      "0 1 1 0.5\n0 2 1 0.5\n0 3 1 0.5\n1 2 1 0.5\n1 3 1 0.5\n2 3 1 0.5\n"
      "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const MeshData d = parsePly(text, "tet.ply");
  REQUIRE(d.positions.empty());
  REQUIRE(d.nVertices == 4);
  REQUIRE(d.edges.size() == 6);
  REQUIRE(d.edges[5].v0 == 2);
  REQUIRE(d.edges[5].v1 == 3);
  REQUIRE(d.edges[5].length == 1.0);
  REQUIRE(d.edgeProperties.at("stress") == std::vector<double>(6, 0.5));
  REQUIRE(d.vertexProperties.at("curvature") == std::vector<double>(4, 3.14159));
  REQUIRE(d.cornerEdges.empty());
  REQUIRE(d.comments == std::vector<std::string>{"regular tetrahedron"});
}

TEST_CASE("PLY: header details (CRLF line ends, geometry comment)", "[mesh_io][ply]") {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment geometry spherical\r\nelement vertex 3\r\nproperty float x\r\n"
      "property float y\r\nproperty float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
      "end_header\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 1 2\r\n";
  const MeshData d = parsePly(text, "crlf.ply");
  REQUIRE(d.background == Background::Spherical);
  REQUIRE(d.comments.empty());
  REQUIRE(d.positions[2] == Eigen::Vector3d(0, 0, 1));
}

// =====================================================================================================================
// Bad input: every message names the file, the line or element, and what was found
// =====================================================================================================================

namespace {
const std::string kTriPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kTriPlyBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
}  // namespace

TEST_CASE("bad input: missing file, directory, unknown extension", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { readMesh("/no/such/dir/mesh.ply"); }),
             Contains("/no/such/dir/mesh.ply") && Contains("no such file"));
  const std::string dir = (scratchDir() / "adir.off").string();
  fs::create_directories(dir);
  CHECK_THAT(errorOf([&] { readMesh(dir); }), Contains(dir) && Contains("directory"));
  CHECK_THAT(errorOf([] { readMesh("mesh.stl"); }), Contains("mesh.stl") && Contains("'.stl'") && Contains(".ply"));
  CHECK_THAT(errorOf([] { formatFromPath("mesh"); }), Contains("no extension"));
}

TEST_CASE("bad input: empty files", "[mesh_io][bad]") {
  const std::string obj = writeFile("empty.obj", ""), off = writeFile("empty.off", ""),
                    ply = writeFile("empty.ply", "");
  CHECK_THAT(errorOf([&] { readMesh(obj); }), Contains(obj) && Contains("empty") && Contains("no faces"));
  CHECK_THAT(errorOf([&] { readMesh(off); }),
             Contains(off + ":1:") && Contains("expected the header keyword OFF") && Contains("found end of file"));
  CHECK_THAT(errorOf([&] { readMesh(ply); }), Contains(ply + ":1:") && Contains("empty file") && Contains("'ply'"));
  // Comments only: still no mesh.
  CHECK_THAT(errorOf([] { parseObj("# nothing\n\n", "c.obj"); }), Contains("c.obj") && Contains("no faces"));
}

TEST_CASE("bad input: truncated ASCII", "[mesh_io][bad]") {
  // The face line is cut after two indices.
  const std::string cut = kTriPlyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1";
  CHECK_THAT(errorOf([&] { parsePly(cut, "cut.ply"); }), Contains("cut.ply:13:") && Contains("face 0") &&
                                                             Contains("vertex_indices") &&
                                                             Contains("found end of file"));
  // A vertex cut short: the long vertex lines make the size check pass, the reader then names the vertex.
  const std::string off = "OFF\n3 1 0\n0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n0.000000 1.000000\n";
  CHECK_THAT(errorOf([&] { parseOff(off, "cut.off"); }),
             Contains("cut.off:5:") && Contains("vertex 2 of 3: coordinate z") && Contains("found end of file"));
  // OBJ cannot be truncated mid-record undetectably only at line ends; a cut index is an out-of-range one.
  CHECK_THAT(errorOf([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 4", "cut.obj"); }),
             Contains("cut.obj:5:") && Contains("vertex index 4") && Contains("3 vertices"));
}

TEST_CASE("bad input: truncated binary", "[mesh_io][bad]") {
  const MeshData d = richOctahedron();
  for (const PlyEncoding enc : {PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    INFO(encodingName(enc));
    const std::string path = (scratchDir() / "trunc.ply").string();
    writeMesh(d, path, {enc});
    const std::string full = readFile(path);
    // Cut inside the last edge record's 'weight' property (each edge: int, int, double, double = 24 bytes).
    const std::string cut = full.substr(0, full.size() - 3);
    CHECK_THAT(errorOf([&] { parsePly(cut, "trunc.ply"); }), Contains("trunc.ply: edge 11: property 'weight'") &&
                                                                 Contains("expected 8 more bytes") &&
                                                                 Contains("found end of data (5 bytes left)"));
    // Cut so that the edge count no longer fits: detected from the header, before reading. The vertices take
    // 6 · 7 doubles = 336 bytes, the faces at least 8 · 2 list-length bytes.
    const std::size_t header = full.find("end_header\n") + 11;
    const std::string text(full, 0, header);
    const int edgeLine = static_cast<int>(std::count(text.begin(), text.begin() + text.find("element edge"), '\n')) + 1;
    CHECK_THAT(errorOf([&] { parsePly(full.substr(0, header + 336 + 16 + 100), "trunc.ply"); }),
               Contains("trunc.ply:" + std::to_string(edgeLine) +
                        ": element edge declares 12 elements of at least 24 "
                        "bytes each, but only 100 bytes of data remain"));
  }
}

TEST_CASE("bad input: garbage tokens", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { parseObj("v 0 0 0\nv 1 abc 0\n", "g.obj"); }),
             Contains("g.obj:2:") && Contains("coordinate y") && Contains("'abc'"));
  CHECK_THAT(errorOf([] { parseObj("v 0 0 0\nvertex 1 2 3\n", "g.obj"); }),
             Contains("g.obj:2:") && Contains("'vertex'"));
  CHECK_THAT(errorOf([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", "g.obj"); }),
             Contains("g.obj:4:") && Contains("'2/x'"));
  CHECK_THAT(errorOf([] { parseObj(std::string("v 0 0 0\n\x01\x02\xff\n", 12), "g.obj"); }),
             Contains("g.obj:2:") && Contains("\\x01\\x02\\xff"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 one 2\n", "g.off"); }),
             Contains("g.off:6:") && Contains("face 0: vertex index 1 of 3") && Contains("'one'"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0 x\n1 0 0\n0 1 0\n3 0 1 2\n", "g.off"); }),
             Contains("g.off:3:") && Contains("'x'"));
  CHECK_THAT(errorOf([] { parseOff("MESH\n", "g.off"); }), Contains("g.off:1:") && Contains("'MESH'"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 0 0\n0 1.0.0 0\n3 0 1 2\n", "g.ply"); }),
             Contains("g.ply:12:") && Contains("vertex 2: property 'y'") && Contains("'1.0.0'"));
  CHECK_THAT(errorOf([] { parsePly("ply\nformat ascii 1.0\nelement vertex 3\nproperty real x\n", "g.ply"); }),
             Contains("g.ply:4:") && Contains("'real'"));
  CHECK_THAT(errorOf([] { parsePly("ply\nformat ascii 1.0\nelemnt vertex 3\n", "g.ply"); }),
             Contains("g.ply:3:") && Contains("'elemnt vertex 3'"));
  CHECK_THAT(errorOf([] { parsePly("PLY\n", "g.ply"); }), Contains("g.ply:1:") && Contains("'PLY'"));
  CHECK_THAT(errorOf([] { parsePly("ply\nformat ascii 1.0\nelement vertex 0\n", "g.ply"); }),
             Contains("g.ply:") && Contains("end_header"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n", "g.ply"); }),
             Contains("g.ply:13:") && Contains("face 0") && Contains("300 is out of range for type uchar"));
  CHECK_THAT(errorOf([] { parsePly("ply\nformat ascii 1.0\ncomment geometry flat\nend_header\n", "g.ply"); }),
             Contains("g.ply:3") && Contains("'flat'"));
}

TEST_CASE("bad input: OBJ vertex index zero, out of range, relative before the start", "[mesh_io][bad][obj]") {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  CHECK_THAT(errorOf([&] { parseObj(v + "f 1 0 2\n", "i.obj"); }),
             Contains("i.obj:4:") && Contains("vertex index 0 is invalid"));
  CHECK_THAT(errorOf([&] { parseObj(v + "f 1 2 3\nf 1 2 9//1\n", "i.obj"); }),
             Contains("i.obj:5:") && Contains("vertex index 9 is out of range") && Contains("3 vertices"));
  CHECK_THAT(errorOf([&] { parseObj(v + "f -1 -2 -4\n", "i.obj"); }),
             Contains("i.obj:4:") && Contains("relative vertex index -4"));
  CHECK_THAT(errorOf([&] { parseObj(v + "f 1 2\n", "i.obj"); }), Contains("i.obj:4:") && Contains("2 corners"));
  CHECK_THAT(errorOf([&] { parseObj(v + "f 1 2 99999999999\n", "i.obj"); }),
             Contains("i.obj:4:") && Contains("99999999999"));
}

TEST_CASE("bad input: OFF and PLY indices out of range", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "r.off"); }),
             Contains("r.off:6:") && Contains("face 0: vertex index 3 is out of range [0, 3)"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "r.off"); }),
             Contains("r.off:6:") && Contains("vertex index -1"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n", "r.ply"); }),
             Contains("r.ply:13: face 0: property 'vertex_indices': vertex index 5 is out of range [0, 3)"));
  Bytes b{false, {}};
  for (int i = 0; i < 9; ++i) b.put<double>(i);
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(-2).put<std::int32_t>(1);
  std::string header = kTriPlyHeader;
  header.replace(header.find("ascii"), 5, "binary_little_endian");
  CHECK_THAT(errorOf([&] { parsePly(header + b.s, "r.ply"); }),
             Contains("r.ply: face 0: property 'vertex_indices': vertex index -2 is out of range [0, 3)"));
}

TEST_CASE("bad input: negative counts", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { parseOff("OFF\n-3 1 0\n", "n.off"); }), Contains("n.off:2:") && Contains("negative count"));
  CHECK_THAT(errorOf([] { parsePly("ply\nformat ascii 1.0\nelement vertex -3\n", "n.ply"); }),
             Contains("n.ply:3:") && Contains("vertex") && Contains("negative count -3"));
  // A negative list length in a signed count type.
  std::string header = kTriPlyHeader;
  header.replace(header.find("list uchar"), 10, "list char");
  CHECK_THAT(errorOf([&] { parsePly(header + "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n", "n.ply"); }),
             Contains("n.ply:13:") && Contains("face 0") && Contains("negative list length -3"));
}

TEST_CASE("bad input: absurd counts in small files are refused before allocating", "[mesh_io][bad]") {
  // 10^12 faces promised by a header of about 100 bytes, in every encoding.
  for (const char* fmt : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    INFO(fmt);
    const std::string text = std::string("ply\nformat ") + fmt +
                             " 1.0\nelement face 1000000000000\nproperty list uchar int vertex_indices\nend_header\n"
                             "3 0 1 2\n";
    CHECK_THAT(
        errorOf([&] { parsePly(text, "big.ply"); }),
        Contains("big.ply:3:") && Contains("element face declares 1000000000000 elements") && Contains("remain"));
  }
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1000000000 0\n0 0 0\n", "big.off"); }),
             Contains("big.off:2:") && Contains("1000000000 faces") && Contains("bytes follow"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1000000000000 0\n0 0 0\n", "big.off"); }),
             Contains("big.off:2:") && Contains("2^31-1"));
  // A list length of 4·10^9 in a 4-byte binary face record.
  Bytes b{false, {}};
  for (int i = 0; i < 9; ++i) b.put<double>(i);
  b.put<std::uint32_t>(4000000000u).put<std::int32_t>(0);
  std::string header = kTriPlyHeader;
  header.replace(header.find("ascii"), 5, "binary_little_endian");
  header.replace(header.find("list uchar"), 10, "list uint");
  CHECK_THAT(errorOf([&] { parsePly(header + b.s, "big.ply"); }),
             Contains("big.ply: face 0: property 'vertex_indices'") && Contains("end of data"));
  // A property-less vertex element costs no bytes; its count is bounded by what the faces can reference.
  CHECK_THAT(errorOf([] {
               parsePly(
                   "ply\nformat ascii 1.0\nelement vertex 2000000000\nelement face 1\n"
                   "property list uchar int vertex_indices\nend_header\n3 0 1 2\n",
                   "big.ply");
             }),
             Contains("big.ply:3:") && Contains("2000000000 vertices without properties"));
}

TEST_CASE("bad input: a face repeating a vertex is named", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n", "rep.obj"); }),
             Contains("rep.obj:5:") && Contains("face 1 repeats vertex 2"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 2\n", "rep.off"); }),
             Contains("rep.off:6:") && Contains("face 0 repeats vertex 2"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 0\n", "rep.ply"); }),
             Contains("rep.ply:13:") && Contains("face 0: repeats vertex 0"));
}

TEST_CASE("bad input: non-finite coordinates and lengths are named", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] { parseObj("v 0 nan 0\n", "nan.obj"); }),
             Contains("nan.obj:1:") && Contains("coordinate y is nan"));
  CHECK_THAT(errorOf([] { parseOff("OFF\n3 1 0\n0 0 0\n1 0 -inf\n0 1 0\n3 0 1 2\n", "inf.off"); }),
             Contains("inf.off:4:") && Contains("vertex 1 of 3: coordinate z is -inf"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "inf.ply"); }),
             Contains("inf.ply:11:") && Contains("vertex 1: property 'y': value is inf"));
  CHECK_THAT(errorOf([&] { parsePly(kTriPlyHeader + "0 0 0\n1 1e999 0\n0 1 0\n3 0 1 2\n", "big.ply"); }),
             Contains("big.ply:11:") && Contains("vertex 1: property 'y'") && Contains("'1e999'"));
  // Binary NaN length on edge 1.
  Bytes b{true, {}};
  b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  b.put<std::int32_t>(0).put<std::int32_t>(1).put<double>(1.0);
  b.put<std::int32_t>(1).put<std::int32_t>(2).put<double>(std::numeric_limits<double>::quiet_NaN());
  const std::string header =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty double length\nend_header\n";
  CHECK_THAT(errorOf([&] { parsePly(header + b.s, "nan.ply"); }),
             Contains("nan.ply: edge 1: property 'length': value is nan"));
}

TEST_CASE("bad input: zero and negative lengths name the edge and its endpoints", "[mesh_io][bad]") {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element edge 3\nproperty double length\nproperty int vertex1\nproperty int vertex2\nend_header\n3 0 1 2\n";
  CHECK_THAT(errorOf([&] { parsePly(header + "1 0 1\n0 1 2\n1 2 0\n", "len.ply"); }),
             Contains("len.ply:13: edge 1:") && Contains("length 0 of the edge joining vertices 1–2 is not positive"));
  CHECK_THAT(errorOf([&] { parsePly(header + "1 0 1\n1 1 2\n-2.5 2 0\n", "len.ply"); }),
             Contains("len.ply:14: edge 2:") && Contains("length -2.5") && Contains("vertices 2–0"));
}

TEST_CASE("bad input: edge_index inconsistent with the faces or the edge element", "[mesh_io][bad]") {
  const MeshData d = oneVertexTorus();
  MeshData bad = richOctahedron();
  std::swap(bad.cornerEdges[2][0], bad.cornerEdges[2][1]);
  const std::string path = (scratchDir() / "badce.ply").string();
  writeMesh(bad, path, {PlyEncoding::Ascii});
  CHECK_THAT(errorOf([&] { readMesh(path); }), Contains(path + ": face 2: edge_index[0]") && Contains("side 0"));
  const std::string noEdges =
      "ply\nformat ascii 1.0\nelement vertex 1\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar int edge_index\nend_header\n3 0 0 0 3 0 1 2\n";
  CHECK_THAT(errorOf([&] { parsePly(noEdges, "ce.ply"); }),
             Contains("ce.ply:4: element face") && Contains("no element edge"));
  const std::string quad =
      "ply\nformat ascii 1.0\nelement vertex 4\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar int edge_index\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
      "property double length\nend_header\n4 0 1 2 3 3 0 0 0\n0 1 1\n";
  CHECK_THAT(errorOf([&] { parsePly(quad, "ce.ply"); }),
             Contains("ce.ply:12: face 0") && Contains("must be triangles"));
}

TEST_CASE("bad input: contradictory geometry lines", "[mesh_io][bad]") {
  CHECK_THAT(errorOf([] {
               parseObj("# geometry spherical\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# geometry hyperbolic\n", "gg.obj");
             }),
             Contains("gg.obj:6:") && Contains("contradicts") && Contains("line 1"));
}

// =====================================================================================================================
// Real files made by others, and speed
// =====================================================================================================================

TEST_CASE("the example files in docs/formats.md parse and build valid triangulations", "[mesh_io][docs]") {
  // Every fenced block tagged obj, off or ply in the format documentation is read as a file of that format; the
  // documentation cannot drift from the readers unnoticed.
  const std::string doc = readFile(std::string(CONFORMESH_SOURCE_DIR) + "/docs/formats.md");
  REQUIRE(!doc.empty());
  int examples = 0;
  std::size_t pos = 0;
  while ((pos = doc.find("\n```", pos)) != std::string::npos) {
    const std::size_t infoEnd = doc.find('\n', pos + 4);
    const std::string tag = doc.substr(pos + 4, infoEnd - pos - 4);
    const std::size_t close = doc.find("\n```\n", infoEnd);
    REQUIRE(close != std::string::npos);
    const std::string body = doc.substr(infoEnd + 1, close - infoEnd);
    pos = close + 4;
    if (tag != "obj" && tag != "off" && tag != "ply") continue;
    INFO("example " << examples << " (" << tag << ")");
    const std::string source = "formats.md example." + tag;
    const MeshData d = tag == "obj"   ? parseObj(body, source)
                       : tag == "off" ? parseOff(body, source)
                                      : parsePly(body, source);
    const IntrinsicTriangulation tri = toTriangulation(d);
    // χ = V − E + F in document order: the square (1), the OFF and PLY tetrahedra (2), the one-vertex torus (0).
    const int expectedChi[] = {1, 2, 2, 0};
    REQUIRE(examples < 4);
    CHECK(tri.mesh.nVertices() - tri.mesh.nEdges() + tri.mesh.nFaces() == expectedChi[examples]);
    ++examples;
  }
  REQUIRE(examples == 4);
}

TEST_CASE("every mesh extracted from CGAL's data set parses and round-trips through every format", "[mesh_io][data]") {
  // tests/CMakeLists.txt extracts these files (made by others, with OFF variants, polygons and comments) at configure
  // time.
  const fs::path root = fs::path(CONFORMESH_TEST_DATA_DIR);
  REQUIRE(fs::is_directory(root));
  int parsed = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".obj" && ext != ".off" && ext != ".ply") continue;
    INFO(entry.path());
    const MeshData d = readMesh(entry.path().string());
    REQUIRE(d.nVertices > 0);
    REQUIRE(static_cast<int>(d.positions.size()) == d.nVertices);
    REQUIRE(d.faces.size() > 0);
    for (const auto& f : d.faces)
      for (int v : f) REQUIRE((v >= 0 && v < d.nVertices));
    for (const char* name : {"real.obj", "real.off", "real.ply"}) {
      const std::string path = (scratchDir() / name).string();
      writeMesh(d, path, {PlyEncoding::BinaryBigEndian});
      MeshData back = readMesh(path);
      requireSameMesh(d, back, true);
    }
    ++parsed;
  }
  REQUIRE(parsed >= 5);
}

// A Stanford-style scan: faces as one `element tristrips` record. The strip 0 1 2 3 4 5 over a 2 × 3 grid of points
// (v_k at x = k/2, y = k mod 2) unrolls to (0,1,2), (2,1,3), (2,3,4), (4,3,5) — odd triangles with their first two
// vertices swapped, so all four share one orientation — then -1 and a second strip 4 5 6 6: its triangle (4,5,6) runs
// along 4→5 against (4,3,5)'s 5→4, and (6,5,6) (the trailing 6 6, a strip join) repeats a vertex: skipped, counted.
TEST_CASE("PLY tristrips are unrolled into consistently oriented triangles, in ASCII and binary", "[mesh_io][ply]") {
  const std::string header =
      "element vertex 7\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  const float xyz[7][3] = {{0, 0, 0}, {0.5f, 1, 0}, {1, 0, 0}, {1.5f, 1, 0}, {2, 0, 0}, {2.5f, 1, 0}, {3, 1, 0}};
  const std::vector<int> strips = {0, 1, 2, 3, 4, 5, -1, 4, 5, 6, 6};
  std::string ascii = "ply\nformat ascii 1.0\n" + header;
  for (const auto& p : xyz) ascii += std::to_string(p[0]) + " " + std::to_string(p[1]) + " 0\n";
  ascii += std::to_string(strips.size());
  for (int v : strips) ascii += " " + std::to_string(v);
  ascii += "\n";
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + header;
  auto put = [&](const void* p, std::size_t n) { binary.append(static_cast<const char*>(p), n); };
  for (const auto& p : xyz) put(p, 12);
  const std::int32_t n = static_cast<std::int32_t>(strips.size());
  put(&n, 4);
  for (std::int32_t v : strips) put(&v, 4);
  for (const std::string* bytes : {&ascii, &binary}) {
    const MeshData d = parsePly(*bytes, "scan.ply");
    const std::vector<std::array<int, 3>> expected = {{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}, {4, 5, 6}};
    CHECK(d.faces == expected);
    CHECK(d.stripTriangles == 5);
    CHECK(d.stripDegenerateSkipped == 1);
    ConversionReport conv;
    const IntrinsicTriangulation tri = toTriangulation(d, &conv);
    CHECK(conv.build.reorientedFaces == 0);  // the strip's own orientation is consistent
    CHECK(conv.stripTriangles == 5);
    CHECK(tri.mesh.nVertices() == 7);
  }
  CHECK_THROWS_WITH(parsePly("ply\nformat ascii 1.0\n" + header + "0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n" +
                                 "3 0 1 9\n",
                             "bad.ply"),
                    Catch::Contains("bad.ply") && Catch::Contains("vertex index 9 is out of range [0, 7)"));
}

TEST_CASE("a face repeating a vertex is refused with the --repair hint, or kept for repair", "[mesh_io][off]") {
  const std::string off = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n4 1 3 3 2\n";
  CHECK_THROWS_WITH(parseOff(off, "q.off"), Catch::Contains("repeats vertex 3") && Catch::Contains("`--repair`"));
  ReadOptions keep;
  keep.keepDegenerateFaces = true;
  const MeshData d = parseOff(off, "q.off", keep);
  CHECK(d.faces.size() == 3);  // the quad's fan: (1, 3, 3) and (1, 3, 2)
  CHECK(d.polygonsTriangulated == 1);
}
