// off_io.cpp — Geomview OFF: the reader (parseOff) and the serializer behind writeMesh(".off").
//
// Read: the header keyword OFF, optionally prefixed by ST, C and/or N (texture coordinates, colours, normals: the extra
// numbers after a vertex's x y z are checked and ignored), then `nv nf ne` (ne ignored), nv vertex records and nf face
// records `n i0 … i(n-1) [colour]`, 0-based, polygons fan-triangulated. Each record ends at the end of the line holding
// its last required number; the numbers after it on that line are the optional extras. `#` comments anywhere (a comment
// "geometry <name>" sets the background). 4OFF, nOFF and binary OFF are rejected by name. Errors: "FILE:LINE: ...".
// Written: OFF with positions and triangles, the geometry line and comments.
#include <algorithm>
#include <climits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "io/mesh_io_internal.h"
#include "io/text_scanner.h"

namespace conformesh::intrinsic {

namespace {

// Consumes the optional extra numbers after a record's required ones, up to the end of the line.
void skipExtrasOnLine(detail::TextScanner& sc, const char* after) {
  for (std::string_view t = sc.tokenOnLine(); !t.empty(); t = sc.tokenOnLine()) {
    double ignored = 0;
    if (!detail::parseReal(t, ignored)) sc.failExpected(std::string("a number or end of line after ") + after, t);
  }
  sc.nextLine();
}

}  // namespace

MeshData parseOff(const std::string& bytes, const std::string& source, const ReadOptions& options) {
  MeshData data;
  data.source = source;
  std::vector<std::pair<int, std::string_view>> comments;
  detail::TextScanner sc(bytes, source);
  sc.enableHashComments(&comments);

  // === header keyword: [ST][C][N][4][n]OFF
  const std::string_view kw = sc.token();
  if (kw.empty()) sc.failExpected("the header keyword OFF", kw);
  std::string_view prefix = kw;
  if (prefix.size() < 3 || prefix.substr(prefix.size() - 3) != "OFF")
    sc.failExpected("the header keyword OFF (or COFF, NOFF, CNOFF, STOFF, ...)", kw);
  prefix.remove_suffix(3);
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  if (prefix.substr(0, 1) == "C") prefix.remove_prefix(1);
  if (prefix.substr(0, 1) == "N") prefix.remove_prefix(1);
  if (prefix == "4" || prefix == "n" || prefix == "4n")
    sc.fail("header keyword " + detail::quoteToken(kw) +
            ": 4-D and n-dimensional OFF are not supported; expected 3-D OFF, COFF, NOFF or STOFF");
  if (!prefix.empty()) sc.failExpected("the header keyword OFF (or COFF, NOFF, CNOFF, STOFF, ...)", kw);

  // === counts
  const std::string_view first = sc.token();
  if (first == "BINARY") sc.fail("binary OFF is not supported; expected the ASCII counts line 'nv nf ne'");
  long long nv = 0, nf = 0, ne = 0;
  if (!detail::parseInteger(first, nv)) sc.failExpected("the vertex count (an integer)", first);
  nf = sc.readInteger([] { return std::string("the face count"); });
  ne = sc.readInteger([] { return std::string("the edge count"); });
  if (nv < 0 || nf < 0 || ne < 0)
    sc.fail("negative count in 'nv nf ne' = " + std::to_string(nv) + " " + std::to_string(nf) + " " +
            std::to_string(ne) + "; expected non-negative integers");
  if (nv > INT_MAX || nf > INT_MAX)
    sc.fail("counts " + std::to_string(nv) + " " + std::to_string(nf) + " exceed the supported maximum 2^31-1");
  if (nf == 0) sc.fail("the face count is 0; expected a triangle mesh");
  // Cheapest records: "0 0 0\n" (6 bytes) and "3 0 1 2\n" (8 bytes); the last newline may be missing. Checking this
  // before reserving memory turns a header that promises 10^9 faces in a short file into a message, not bad_alloc.
  const long long needed = nv * 6 + nf * 8 - 1;
  if (needed > static_cast<long long>(sc.remainingBytes()))
    sc.fail("the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
            " faces, which need at least " + std::to_string(needed) + " bytes, but only " +
            std::to_string(sc.remainingBytes()) + " bytes follow");
  sc.nextLine();
  data.nVertices = static_cast<int>(nv);
  data.positions.resize(static_cast<std::size_t>(nv));
  data.faces.reserve(static_cast<std::size_t>(nf));

  // === vertices
  for (long long i = 0; i < nv; ++i) {
    Eigen::Vector3d& p = data.positions[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k)
      p[k] = sc.readFinite(
          [&] { return "vertex " + std::to_string(i) + " of " + std::to_string(nv) + ": coordinate " + "xyz"[k]; });
    skipExtrasOnLine(sc, "the vertex coordinates");
  }

  // === faces
  std::vector<int> corners;
  for (long long f = 0; f < nf; ++f) {
    const long long n = sc.readInteger(
        [&] { return "face " + std::to_string(f) + " of " + std::to_string(nf) + ": the number of its vertices"; });
    if (n < 3) sc.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; expected at least 3");
    corners.clear();
    for (long long k = 0; k < n; ++k) {
      const long long v = sc.readInteger([&] {
        return "face " + std::to_string(f) + ": vertex index " + std::to_string(k) + " of " + std::to_string(n);
      });
      if (v < 0 || v >= nv)
        sc.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(v) + " is out of range [0, " +
                std::to_string(nv) + ")");
      corners.push_back(static_cast<int>(v));
    }
    if (n > 3) ++data.polygonsTriangulated;
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      const int a = corners[0], b = corners[k], c = corners[k + 1];
      if ((a == b || b == c || a == c) && !options.keepDegenerateFaces)
        sc.fail("face " + std::to_string(f) + " repeats vertex " + std::to_string(a == b || a == c ? a : b) +
                "; a triangle needs three distinct vertices (`--repair` drops such faces)");
      data.faces.push_back({a, b, c});
    }
    skipExtrasOnLine(sc, "the face's vertex indices (a colour)");
  }
  detail::applyHashComments(comments, data);
  return data;
}

namespace detail {

std::string serializeOff(const MeshData& data) {
  std::string out;
  out.reserve(data.positions.size() * 48 + data.faces.size() * 24 + 256);
  out += "OFF\n# geometry " + toString(data.background) + "\n";
  for (const std::string& c : data.comments) out += "# " + c + "\n";
  appendInt(out, data.nVertices);
  out += ' ';
  appendInt(out, static_cast<long long>(data.faces.size()));
  out += " 0\n";
  for (const Eigen::Vector3d& p : data.positions) {
    appendReal(out, p.x());
    out += ' ';
    appendReal(out, p.y());
    out += ' ';
    appendReal(out, p.z());
    out += '\n';
  }
  for (const auto& f : data.faces) {
    out += "3 ";
    appendInt(out, f[0]);
    out += ' ';
    appendInt(out, f[1]);
    out += ' ';
    appendInt(out, f[2]);
    out += '\n';
  }
  return out;
}

}  // namespace detail

}  // namespace conformesh::intrinsic
