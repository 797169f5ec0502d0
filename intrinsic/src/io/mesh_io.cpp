// mesh_io.cpp — the format-independent half of mesh I/O: the format from a file name, reading a whole file into memory
// and dispatching to parseObj/parseOff/parsePly, and writing by serializing to memory first and then replacing the
// target atomically (write a temporary file beside it, then rename), so that a failed write never leaves a truncated
// mesh where a good one was.
//
// Also the checks shared by the writers (validateForWriting) and the `geometry <name>` comment convention shared by the
// readers. The per-format code is in obj_io.cpp, off_io.cpp and ply_io.cpp; docs/formats.md describes the formats.
#include "conformesh/intrinsic/io/mesh_io.h"

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"
#include "io/mesh_io_internal.h"
#include "io/text_scanner.h"

namespace conformesh::intrinsic {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The whole file in one read: the parsers work on memory (binary PLY by memcpy, text by std::from_chars).
std::string readWholeFile(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InputError(path + ": cannot open: no such file");
  if (std::filesystem::is_directory(status)) throw InputError(path + ": cannot read: it is a directory, not a file");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw InputError(path + ": cannot open: " + std::strerror(errno));
  std::string bytes;
  char buffer[1 << 16];
  // Reading to end of file (rather than trusting a size query) also works for pipes and files that change size.
  if (std::filesystem::is_regular_file(status)) {
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  }
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, f);
    bytes.append(buffer, n);
    if (n < sizeof buffer) break;
  }
  const bool failed = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (failed) throw InputError(path + ": read error: " + std::strerror(err));
  return bytes;
}


bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// A PLY property name must be one header word: printable, no blanks.
bool isPlyWord(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u >= 0x7f) return false;
  }
  return true;
}

}  // namespace

// === format dispatch

MeshFormat formatFromPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".ply") return MeshFormat::Ply;
  throw InputError(path + ": unknown mesh format " + (ext.empty() ? std::string("(no extension)") : "'" + ext + "'") +
                   "; expected a file name ending in .obj, .off or .ply");
}

MeshData readMesh(const std::string& path, const ReadOptions& options) {
  const MeshFormat format = formatFromPath(path);
  const std::string bytes = readWholeFile(path);
  switch (format) {
    case MeshFormat::Obj:
      return parseObj(bytes, path, options);
    case MeshFormat::Off:
      return parseOff(bytes, path, options);
    case MeshFormat::Ply:
      break;
  }
  return parsePly(bytes, path, options);
}

void writeMesh(const MeshData& data, const std::string& path, const WriteOptions& options) {
  const MeshFormat format = formatFromPath(path);
  detail::validateForWriting(data, path, format != MeshFormat::Ply);
  std::string bytes;
  switch (format) {
    case MeshFormat::Obj:
      bytes = detail::serializeObj(data);
      break;
    case MeshFormat::Off:
      bytes = detail::serializeOff(data);
      break;
    case MeshFormat::Ply:
      bytes = detail::serializePly(data, options.plyEncoding);
      break;
  }
  writeFileAtomically(path, bytes);
}

// === shared by the readers and writers

namespace detail {

bool parseGeometryComment(std::string_view comment, const std::string& where, Background& background) {
  std::string_view words[3];
  int n = 0;
  std::size_t i = 0;
  while (i < comment.size() && n < 3) {
    while (i < comment.size() && isBlank(comment[i])) ++i;
    const std::size_t begin = i;
    while (i < comment.size() && !isBlank(comment[i])) ++i;
    if (i > begin) words[n++] = comment.substr(begin, i - begin);
  }
  if (n != 2 || words[0] != "geometry") return false;
  background = backgroundFromString(std::string(words[1]), where);
  return true;
}

void applyHashComments(const std::vector<std::pair<int, std::string_view>>& comments, MeshData& data) {
  int geometryLine = 0;
  for (const auto& [line, text] : comments) {
    const std::string where = data.source + ":" + std::to_string(line);
    Background g = Background::Euclidean;
    if (parseGeometryComment(text, where, g)) {
      if (geometryLine != 0 && g != data.background)
        throw InputError(where + ": geometry " + toString(g) + " contradicts geometry " + toString(data.background) +
                         " declared on line " + std::to_string(geometryLine));
      data.background = g;
      geometryLine = line;
    } else {
      data.comments.emplace_back(text);
    }
  }
}

void validateForWriting(const MeshData& data, const std::string& path, bool needPositions) {
  const auto fail = [&](const std::string& what) { throw InputError(path + ": cannot write: " + what); };
  const int n = data.nVertices;
  if (n < 0) fail("nVertices is " + std::to_string(n));
  if (data.faces.empty()) fail("the mesh has no faces");
  if (needPositions && data.positions.empty())
    fail(
        "the mesh has no vertex positions (it is metric-only); OBJ and OFF cannot carry edge lengths, write a .ply "
        "file instead");
  if (!data.positions.empty() && static_cast<long long>(data.positions.size()) != n)
    fail(std::to_string(data.positions.size()) + " positions for " + std::to_string(n) + " vertices");
  for (std::size_t v = 0; v < data.positions.size(); ++v)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(data.positions[v][k]))
        fail("vertex " + std::to_string(v) + ": coordinate " + "xyz"[k] + " is " + formatNumber(data.positions[v][k]));
  for (std::size_t f = 0; f < data.faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (data.faces[f][k] < 0 || data.faces[f][k] >= n)
        fail("face " + std::to_string(f) + ": vertex index " + std::to_string(data.faces[f][k]) + " out of range [0, " +
             std::to_string(n) + ")");
  const long long nEdges = static_cast<long long>(data.edges.size());
  for (std::size_t e = 0; e < data.edges.size(); ++e) {
    const EdgeRecord& r = data.edges[e];
    if (r.v0 < 0 || r.v0 >= n || r.v1 < 0 || r.v1 >= n)
      fail("edge " + std::to_string(e) + ": vertex index out of range [0, " + std::to_string(n) + ")");
    if (!std::isfinite(r.length) || !(r.length > 0))
      fail("edge " + std::to_string(e) + ": length is " + formatNumber(r.length) +
           "; expected a finite positive length");
  }
  if (!data.cornerEdges.empty()) {
    if (data.cornerEdges.size() != data.faces.size())
      fail(std::to_string(data.cornerEdges.size()) + " cornerEdges rows for " + std::to_string(data.faces.size()) +
           " faces");
    for (std::size_t f = 0; f < data.cornerEdges.size(); ++f)
      for (int k = 0; k < 3; ++k)
        if (data.cornerEdges[f][k] < 0 || data.cornerEdges[f][k] >= nEdges)
          fail("face " + std::to_string(f) + ": edge_index " + std::to_string(data.cornerEdges[f][k]) +
               " out of range [0, " + std::to_string(nEdges) + ")");
  }
  const auto checkProperties = [&](const std::map<std::string, std::vector<double>>& props, const char* element,
                                   std::size_t count) {
    for (const auto& [name, values] : props) {
      if (!isPlyWord(name)) fail(std::string(element) + " property name " + quoteToken(name) + " is not one word");
      if (values.size() != count)
        fail(std::string(element) + " property '" + name + "' has " + std::to_string(values.size()) + " values for " +
             std::to_string(count) + " " + element + "s");
      for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
          fail(std::string(element) + " " + std::to_string(i) + ": property '" + name + "' is " +
               formatNumber(values[i]));
    }
  };
  checkProperties(data.vertexProperties, "vertex", static_cast<std::size_t>(n));
  checkProperties(data.edgeProperties, "edge", data.edges.size());
  for (const char* reserved : {"x", "y", "z"})
    if (data.vertexProperties.count(reserved))
      fail(std::string("vertex property '") + reserved + "' would be read back as a coordinate; use positions");
  for (const char* reserved : {"vertex1", "vertex2", "length"})
    if (data.edgeProperties.count(reserved))
      fail(std::string("edge property '") + reserved + "' clashes with the edge element's own property");
  for (std::size_t i = 0; i < data.comments.size(); ++i) {
    const std::string& c = data.comments[i];
    if (c.find_first_of("\r\n") != std::string::npos) fail("comment " + std::to_string(i) + " contains a line break");
    Background g = Background::Euclidean;
    bool isGeometry = false;
    try {
      isGeometry = parseGeometryComment(c, path, g);
    } catch (const InputError&) {
      isGeometry = true;  // "geometry <unknown>" would fail to read back
    }
    if (isGeometry)
      fail("comment " + std::to_string(i) + " '" + c + "' would be read back as the geometry line; set background");
  }
}

}  // namespace detail

}  // namespace conformesh::intrinsic
