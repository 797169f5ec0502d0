// obj_io.cpp — Wavefront OBJ: the reader (parseObj) and the serializer behind writeMesh(".obj").
//
// Read: `v x y z [w | r g b [a]]` (extra numbers ignored), `f` with corners `i`, `i/t`, `i//n`, `i/t/n` (only the
// vertex index is used; negative indices count back from the last vertex read so far), polygons fan-triangulated from
// their first corner; texture/normal/grouping/material statements and free-form geometry keywords are ignored; `#`
// comments are kept (a comment "geometry <name>" sets the background). Anything else is an InputError "FILE:LINE: ...".
// Written: `v` and `f` lines (1-based), the geometry line and the comments. OBJ cannot carry edge lengths or
// properties; docs/formats.md says so.
#include <algorithm>
#include <climits>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "io/mesh_io_internal.h"
#include "io/text_scanner.h"

namespace conformesh::intrinsic {

namespace {

// Statements of the OBJ specification (and common extensions) that carry nothing a triangle mesh with lengths needs.
bool isIgnoredObjStatement(std::string_view kw) {
  static const std::unordered_set<std::string_view> ignored = {
      "vt",         "vn",        "vp",    "g",     "o",    "s",     "usemtl",   "mtllib",   "l",      "p",
      "cstype",     "deg",       "bmat",  "step",  "curv", "curv2", "surf",     "parm",     "trim",   "hole",
      "scrv",       "sp",        "end",   "con",   "lod",  "bevel", "c_interp", "d_interp", "usemap", "maplib",
      "shadow_obj", "trace_obj", "ctech", "stech", "mg",   "call",  "csh"};
  return ignored.count(kw) != 0;
}

// A positive index beyond the vertices read so far: legal only if enough vertices follow, checked at the end.
struct ForwardReference {
  int line;
  long long index;  // 1-based, as written
};

}  // namespace

MeshData parseObj(const std::string& bytes, const std::string& source, const ReadOptions& options) {
  MeshData data;
  data.source = source;
  std::vector<std::pair<int, std::string_view>> comments;
  detail::TextScanner sc(bytes, source);
  sc.enableHashComments(&comments);
  // A vertex line has at least 6 bytes ("v 0 0 0" minus separators) and a triangle line at least 8: reserving by those
  // bounds never allocates more than the input justifies.
  data.positions.reserve(std::min<std::size_t>(bytes.size() / 64, 1u << 20));
  data.faces.reserve(std::min<std::size_t>(bytes.size() / 64, 1u << 21));

  std::vector<ForwardReference> forward;
  std::vector<long long> corners;  // 1-based (resolved) indices of the current polygon
  do {
    const std::string_view kw = sc.tokenOnLine();
    if (kw.empty()) continue;
    if (kw == "v") {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k)
        p[k] = sc.readFinite([&] { return std::string("vertex coordinate ") + "xyz"[k]; }, true);
      // Optional w (rational weight, meaningless for a polygon mesh) or an RGB(A) colour: checked, then ignored.
      for (std::string_view t = sc.tokenOnLine(); !t.empty(); t = sc.tokenOnLine()) {
        double ignored = 0;
        if (!detail::parseReal(t, ignored)) sc.failExpected("a number or end of line after the vertex coordinates", t);
      }
      if (data.positions.size() == static_cast<std::size_t>(INT_MAX)) sc.fail("more than 2^31-1 vertices");
      data.positions.push_back(p);
    } else if (kw == "f") {
      const long long nSoFar = static_cast<long long>(data.positions.size());
      corners.clear();
      for (std::string_view t = sc.tokenOnLine(); !t.empty(); t = sc.tokenOnLine()) {
        // i, i/t, i//n or i/t/n: the vertex index, then at most two slash-separated integers (t may be empty).
        const std::size_t slash = t.find('/');
        const std::string_view vertexPart = t.substr(0, slash);
        long long index = 0;
        if (!detail::parseInteger(vertexPart, index))
          sc.failExpected("a face corner 'v', 'v/t', 'v//n' or 'v/t/n' with integer v", t);
        if (slash != std::string_view::npos) {
          std::string_view rest = t.substr(slash + 1);
          const std::size_t slash2 = rest.find('/');
          const std::string_view texPart = rest.substr(0, slash2);
          const std::string_view normalPart =
              slash2 == std::string_view::npos ? std::string_view() : rest.substr(slash2 + 1);
          long long ignored = 0;
          const bool texOk =
              texPart.empty() ? slash2 != std::string_view::npos : detail::parseInteger(texPart, ignored);
          const bool normalOk = slash2 == std::string_view::npos || detail::parseInteger(normalPart, ignored);
          if (!texOk || !normalOk) sc.failExpected("a face corner 'v', 'v/t', 'v//n' or 'v/t/n'", t);
        }
        if (index == 0)
          sc.fail("face corner " + detail::quoteToken(t) + ": vertex index 0 is invalid (OBJ indices start at 1)");
        if (index < 0) {
          if (-index > nSoFar)
            sc.fail("face corner " + detail::quoteToken(t) + ": relative vertex index " + std::to_string(index) +
                    " reaches before the first vertex (" + std::to_string(nSoFar) + " vertices read so far)");
          index = nSoFar + index + 1;
        } else if (index > nSoFar) {
          if (index > INT_MAX)
            sc.fail("face corner " + detail::quoteToken(t) + ": vertex index " + std::to_string(index) +
                    " is out of range (more than 2^31-1)");
          forward.push_back({sc.line(), index});
        }
        corners.push_back(index);
      }
      if (corners.size() < 3)
        sc.fail("face has " + std::to_string(corners.size()) + " corner" + (corners.size() == 1 ? "" : "s") +
                "; expected at least 3");
      if (corners.size() > 3) ++data.polygonsTriangulated;
      // Fan triangulation from the first corner; each triangle must have three distinct vertices.
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        const long long a = corners[0], b = corners[k], c = corners[k + 1];
        if ((a == b || b == c || a == c) && !options.keepDegenerateFaces)
          sc.fail("face " + std::to_string(data.faces.size()) + " repeats vertex " +
                  std::to_string(a == b || a == c ? a : b) +
                  " (1-based); a triangle needs three distinct vertices (`--repair` drops such faces)");
        data.faces.push_back({static_cast<int>(a - 1), static_cast<int>(b - 1), static_cast<int>(c - 1)});
      }
    } else if (!isIgnoredObjStatement(kw)) {
      sc.failExpected("an OBJ statement (v, f, or one of vt vn g o s usemtl mtllib ...)", kw);
    }
  } while (sc.nextLine());

  data.nVertices = static_cast<int>(data.positions.size());
  for (const ForwardReference& r : forward)
    if (r.index > data.nVertices)
      throw InputError(source + ":" + std::to_string(r.line) + ": face vertex index " + std::to_string(r.index) +
                       " is out of range; the file has " + std::to_string(data.nVertices) + " vertices");
  if (data.faces.empty())
    throw InputError(source + ": no faces (no 'f' lines" + (bytes.empty() ? ", the file is empty" : std::string()) +
                     "); expected a triangle mesh");
  detail::applyHashComments(comments, data);
  return data;
}

namespace detail {

std::string serializeObj(const MeshData& data) {
  std::string out;
  out.reserve(data.positions.size() * 48 + data.faces.size() * 24 + 256);
  out += "# geometry " + toString(data.background) + "\n";
  for (const std::string& c : data.comments) out += "# " + c + "\n";
  for (const Eigen::Vector3d& p : data.positions) {
    out += "v ";
    appendReal(out, p.x());
    out += ' ';
    appendReal(out, p.y());
    out += ' ';
    appendReal(out, p.z());
    out += '\n';
  }
  for (const auto& f : data.faces) {
    out += "f ";
    appendInt(out, f[0] + 1LL);
    out += ' ';
    appendInt(out, f[1] + 1LL);
    out += ' ';
    appendInt(out, f[2] + 1LL);
    out += '\n';
  }
  return out;
}

}  // namespace detail

}  // namespace conformesh::intrinsic
