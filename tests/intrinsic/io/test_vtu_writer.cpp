// test_vtu_writer.cpp — the VTK XML UnstructuredGrid writer (vtu_writer.h).
//
// The written file is parsed back here with a reader of its own (attribute scanning and a base64 decoder written from
// RFC 4648, not the writer's), and every array is compared with the mesh it came from: points, connectivity, offsets,
// cell types, each field's name, component count, length and values — bit for bit, since the arrays are binary (NaN,
// ±inf, −0 and subnormals included). Bad input must raise InputError naming the path and element and leave no file.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/vtu_writer.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::intrinsic;
using Catch::Matchers::Contains;
using conformesh::InputError;
namespace fs = std::filesystem;

namespace {

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("conformesh_vtu_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const auto start = at + name.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (size_t at; (at = s.find(from)) != std::string::npos;) s.replace(at, std::strlen(from), to);
  return s;
}

std::string decodeBase64(const std::string& text) {
  std::string out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else
      continue;  // white space and '=' padding
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 0xFF);
    }
  }
  return out;
}

struct ParsedArray {
  std::string type, name, section;
  int components = 0;
  std::string bytes;  // payload after the UInt64 byte count
};

struct ParsedVtu {
  std::string fileTag, pieceTag, pointDataTag;
  std::vector<ParsedArray> arrays;
  const ParsedArray& get(const std::string& name) const {
    for (const auto& a : arrays)
      if (a.name == name) return a;
    FAIL("no array named " << name);
    return arrays.front();
  }
  template <class T>
  std::vector<T> values(const std::string& name) const {
    const auto& b = get(name).bytes;
    std::vector<T> v(b.size() / sizeof(T));
    std::memcpy(v.data(), b.data(), b.size());
    return v;
  }
};

std::string tagAt(const std::string& xml, const std::string& open) {
  const auto at = xml.find(open);
  REQUIRE(at != std::string::npos);
  return xml.substr(at, xml.find('>', at) - at);
}

ParsedVtu parseVtu(const std::string& xml) {
  ParsedVtu p;
  p.fileTag = tagAt(xml, "<VTKFile ");
  p.pieceTag = tagAt(xml, "<Piece ");
  p.pointDataTag = tagAt(xml, "<PointData");
  for (size_t at = 0; (at = xml.find("<DataArray ", at)) != std::string::npos;) {
    const auto close = xml.find('>', at);
    const std::string tag = xml.substr(at, close - at);
    const auto end = xml.find("</DataArray>", close);
    ParsedArray a;
    a.type = attribute(tag, "type");
    a.name = unescape(attribute(tag, "Name"));
    a.components = std::stoi(attribute(tag, "NumberOfComponents"));
    const auto cells = xml.rfind("<Cells>", at), points = xml.rfind("<Points>", at), pd = xml.rfind("<PointData", at);
    a.section = cells != std::string::npos    ? "Cells"
                : points != std::string::npos ? "Points"
                : pd != std::string::npos     ? "PointData"
                                              : "";
    REQUIRE(attribute(tag, "format") == "binary");
    const std::string raw = decodeBase64(xml.substr(close + 1, end - close - 1));
    REQUIRE(raw.size() >= 8);
    uint64_t nbytes;
    std::memcpy(&nbytes, raw.data(), 8);
    REQUIRE(nbytes == raw.size() - 8);  // the header counts exactly the payload
    a.bytes = raw.substr(8);
    p.arrays.push_back(a);
    at = end;
  }
  return p;
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

VtkMesh icosphereWithFields(std::vector<Eigen::Vector2d>& chart) {
  const MeshData ico = makeIcosphere({1, 1.0});
  VtkMesh m;
  m.title = "icosphere <level 1> & fields";
  m.points = ico.positions;
  m.triangles = ico.faces;
  const size_t n = m.points.size();
  auto& height = m.pointFields["height"];
  auto& special = m.pointFields["special \"values\" <&>"];
  for (size_t v = 0; v < n; ++v) {
    const auto& p = m.points[v];
    height.push_back(p.z());
    chart.emplace_back(std::atan2(p.y(), p.x()), std::acos(std::max(-1.0, std::min(1.0, p.z()))));
  }
  special.assign(n, 0.5);
  special[0] = std::numeric_limits<double>::quiet_NaN();
  special[1] = std::numeric_limits<double>::infinity();
  special[2] = -std::numeric_limits<double>::infinity();
  special[3] = -0.0;
  special[4] = std::numeric_limits<double>::denorm_min();
  special[5] = std::numeric_limits<double>::max();
  return m;
}

}  // namespace

TEST_CASE("writeVtu: every array reads back bit for bit with its name, length and section", "[io][vtu]") {
  std::vector<Eigen::Vector2d> chart;
  const VtkMesh m = icosphereWithFields(chart);
  const std::string path = tempPath("round.vtu");
  writeVtu(m, path, chart);
  REQUIRE_FALSE(fs::exists(path + ".tmp"));
  const std::string xml = slurp(path);
  const ParsedVtu p = parseVtu(xml);
  const size_t n = m.points.size(), f = m.triangles.size();
  REQUIRE(n == 42);  // icosphere level 1: 10·4 + 2 vertices, 80 faces
  REQUIRE(f == 80);
  CHECK(attribute(p.fileTag, "type") == "UnstructuredGrid");
  CHECK(attribute(p.fileTag, "header_type") == "UInt64");
  CHECK(attribute(p.fileTag, "byte_order") == "LittleEndian");  // x86-64 and aarch64 Linux
  CHECK(attribute(p.pieceTag, "NumberOfPoints") == std::to_string(n));
  CHECK(attribute(p.pieceTag, "NumberOfCells") == std::to_string(f));
  CHECK(attribute(p.pointDataTag, "TCoords") == "chart");
  CHECK_THAT(xml, Contains("icosphere &lt;level 1&gt; &amp; fields"));
  REQUIRE(p.arrays.size() == 7);  // two fields, chart, points, connectivity, offsets, types

  const auto xyz = p.values<double>("Points");
  CHECK(p.get("Points").section == "Points");
  CHECK(p.get("Points").components == 3);
  REQUIRE(xyz.size() == 3 * n);
  for (size_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) CHECK(sameBits(xyz[3 * v + k], m.points[v][k]));

  const auto conn = p.values<int64_t>("connectivity");
  const auto offsets = p.values<int64_t>("offsets");
  const auto types = p.values<uint8_t>("types");
  CHECK(p.get("connectivity").type == "Int64");
  CHECK(p.get("types").type == "UInt8");
  CHECK(p.get("types").section == "Cells");
  REQUIRE(conn.size() == 3 * f);
  REQUIRE(offsets.size() == f);
  REQUIRE(types.size() == f);
  for (size_t t = 0; t < f; ++t) {
    CHECK(offsets[t] == static_cast<int64_t>(3 * (t + 1)));
    CHECK(types[t] == 5);  // VTK_TRIANGLE
    for (int k = 0; k < 3; ++k) CHECK(conn[3 * t + k] == m.triangles[t][k]);
  }

  for (const auto& [name, values] : m.pointFields) {
    INFO(name);
    const auto& a = p.get(name);
    CHECK(a.type == "Float64");
    CHECK(a.section == "PointData");
    CHECK(a.components == 1);
    const auto read = p.values<double>(name);
    REQUIRE(read.size() == n);
    for (size_t v = 0; v < n; ++v) CHECK(sameBits(read[v], values[v]));
  }
  const auto uv = p.values<double>("chart");
  CHECK(p.get("chart").components == 2);
  REQUIRE(uv.size() == 2 * n);
  for (size_t v = 0; v < n; ++v) CHECK((sameBits(uv[2 * v], chart[v].x()) && sameBits(uv[2 * v + 1], chart[v].y())));
  fs::remove(path);
}

TEST_CASE("writeVtu: no chart, no fields, and an empty mesh are valid files", "[io][vtu]") {
  VtkMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  const std::string path = tempPath("plain.vtu");
  writeVtu(m, path);
  ParsedVtu p = parseVtu(slurp(path));
  CHECK(attribute(p.pointDataTag, "TCoords").empty());
  CHECK(p.arrays.size() == 4);
  CHECK(p.values<int64_t>("offsets") == std::vector<int64_t>{3});
  writeVtu(VtkMesh{}, path);
  p = parseVtu(slurp(path));
  CHECK(attribute(p.pieceTag, "NumberOfPoints") == "0");
  CHECK(p.values<double>("Points").empty());
  fs::remove(path);
}

TEST_CASE("writeVtu: bad input names the path and element and leaves no file", "[io][vtu][errors]") {
  std::vector<Eigen::Vector2d> chart;
  VtkMesh m = icosphereWithFields(chart);
  const std::string path = tempPath("bad.vtu");
  fs::remove(path);
  auto expectError = [&](const VtkMesh& mesh, const std::vector<Eigen::Vector2d>& c, const std::string& what) {
    REQUIRE_THROWS_WITH(writeVtu(mesh, path, c), Contains(path) && Contains(what));
    CHECK_FALSE(fs::exists(path));
    CHECK_FALSE(fs::exists(path + ".tmp"));
  };
  VtkMesh shortField = m;
  shortField.pointFields["height"].pop_back();
  expectError(shortField, chart, "field 'height' has 41 values, expected one per point (42)");
  expectError(m, std::vector<Eigen::Vector2d>(chart.begin(), chart.end() - 2), "chart has 40 coordinates");
  VtkMesh badIndex = m;
  badIndex.triangles[7][1] = 42;
  expectError(badIndex, chart, "triangle 7 refers to point 42 of 42");
  VtkMesh unnamed = m;
  unnamed.pointFields[""] = m.pointFields["height"];
  expectError(unnamed, chart, "empty name");
  VtkMesh clash = m;
  clash.pointFields["chart"] = m.pointFields["height"];
  expectError(clash, chart, "'chart' clashes");
  REQUIRE_THROWS_AS(writeVtu(m, "/nonexistent-dir/x.vtu", chart), InputError);
}
