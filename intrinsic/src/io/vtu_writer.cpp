// vtu_writer.cpp — VTK XML UnstructuredGrid writer with inline base64 binary arrays (vtu_writer.h).
#include "conformesh/intrinsic/io/vtu_writer.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"

namespace conformesh::intrinsic {

namespace {

// Base64 (RFC 4648, with padding) of a byte string.
std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t w = 0;
    for (size_t k = 0; k < 3; ++k) w = (w << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? table[(w >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// VTK's uncompressed binary block: the payload's byte count as UInt64, then the payload, base64-encoded together.
template <class T>
std::string encodeBlock(const std::vector<T>& values) {
  const uint64_t nbytes = values.size() * sizeof(T);
  std::string raw(sizeof nbytes + nbytes, '\0');
  std::memcpy(&raw[0], &nbytes, sizeof nbytes);
  if (nbytes) std::memcpy(&raw[sizeof nbytes], values.data(), nbytes);
  return base64(raw);
}

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

template <class T>
void writeArray(std::ostream& out, const char* type, const std::string& name, int components,
                const std::vector<T>& values) {
  out << "        <DataArray type=\"" << type << "\"";
  if (!name.empty()) out << " Name=\"" << xmlEscape(name) << "\"";
  out << " NumberOfComponents=\"" << components << "\" format=\"binary\">\n          " << encodeBlock(values)
      << "\n        </DataArray>\n";
}

void validate(const VtkMesh& mesh, const std::string& path, const std::vector<Eigen::Vector2d>& chart) {
  const size_t n = mesh.points.size();
  for (const auto& [name, values] : mesh.pointFields) {
    if (name.empty()) throw InputError(describeAt(path, "a point field has an empty name"));
    if (name == "chart" && !chart.empty())
      throw InputError(describeAt(path, "point field 'chart' clashes with the chart coordinates' array"));
    if (values.size() != n)
      throw InputError(describeAt(path, "field '" + name + "' has " + std::to_string(values.size()) +
                                            " values, expected one per point (" + std::to_string(n) + ")"));
  }
  if (!chart.empty() && chart.size() != n)
    throw InputError(describeAt(path, "chart has " + std::to_string(chart.size()) +
                                          " coordinates, expected one per point (" + std::to_string(n) + ")"));
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int v : mesh.triangles[f])
      if (v < 0 || static_cast<size_t>(v) >= n)
        throw InputError(describeAt(path, "triangle " + std::to_string(f) + " refers to point " + std::to_string(v) +
                                              " of " + std::to_string(n)));
}

void writeBody(std::ostream& out, const VtkMesh& mesh, const std::vector<Eigen::Vector2d>& chart) {
  const uint16_t probe = 1;
  const bool little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  out << "<?xml version=\"1.0\"?>\n<!-- " << xmlEscape(mesh.title) << " -->\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << (little ? "LittleEndian" : "BigEndian")
      << "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << mesh.points.size()
      << "\" NumberOfCells=\"" << mesh.triangles.size() << "\">\n      <PointData";
  if (!chart.empty()) out << " TCoords=\"chart\"";
  out << ">\n";
  for (const auto& [name, values] : mesh.pointFields) writeArray(out, "Float64", name, 1, values);
  if (!chart.empty()) {
    std::vector<double> uv;
    for (const auto& c : chart) uv.insert(uv.end(), {c.x(), c.y()});
    writeArray(out, "Float64", "chart", 2, uv);
  }
  out << "      </PointData>\n      <Points>\n";
  std::vector<double> xyz;
  for (const auto& p : mesh.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  writeArray(out, "Float64", "Points", 3, xyz);
  out << "      </Points>\n      <Cells>\n";
  std::vector<int64_t> connectivity, offsets;
  for (const auto& t : mesh.triangles) {
    connectivity.insert(connectivity.end(), {t[0], t[1], t[2]});
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
  }
  writeArray(out, "Int64", "connectivity", 1, connectivity);
  writeArray(out, "Int64", "offsets", 1, offsets);
  writeArray(out, "UInt8", "types", 1, std::vector<uint8_t>(mesh.triangles.size(), 5));  // VTK_TRIANGLE
  out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void writeVtu(const VtkMesh& mesh, const std::string& path, const std::vector<Eigen::Vector2d>& chart) {
  validate(mesh, path, chart);
  std::ostringstream out;
  writeBody(out, mesh, chart);
  writeFileAtomically(path, out.str());
}

}  // namespace conformesh::intrinsic
