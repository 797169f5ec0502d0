// mesh_io_internal.h — private to the mesh readers and writers: the per-format serializers that writeMesh() dispatches
// to, the check that a MeshData is consistent enough to be written, and the `geometry <name>` comment convention that
// all three formats share ("comment geometry spherical" in a PLY header, "# geometry spherical" in OBJ and OFF).
//
// Not installed; mesh_io.h is the public interface.
#pragma once

#include <charconv>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/io/mesh_io.h"

namespace conformesh::intrinsic::detail {

// Whole files as bytes. Each requires validateForWriting() to have passed.
std::string serializeObj(const MeshData& data);
std::string serializeOff(const MeshData& data);
std::string serializePly(const MeshData& data, PlyEncoding encoding);

// Throws InputError naming `path` and the element when `data` cannot be written faithfully: face or edge indices out of
// range, arrays of the wrong length, non-finite numbers, property names a PLY header cannot hold, comments with line
// breaks or that would read back as a geometry line. `needPositions` for OBJ and OFF.
void validateForWriting(const MeshData& data, const std::string& path, bool needPositions);

// When `comment` is exactly "geometry <name>" (two blank-separated words), sets `background` from <name> (an unknown
// name is an InputError naming `where`) and returns true; otherwise returns false and leaves `background` alone.
bool parseGeometryComment(std::string_view comment, const std::string& where, Background& background);

// Files the `#` comments collected by a TextScanner (OBJ, OFF): geometry lines set data.background, the others are
// appended to data.comments. A second geometry line that disagrees with the first is an InputError.
void applyHashComments(const std::vector<std::pair<int, std::string_view>>& comments, MeshData& data);

// Shortest text that reads back as exactly `x` (std::to_chars), and plain integers, appended to `out`.
inline void appendReal(std::string& out, double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}
inline void appendInt(std::string& out, long long x) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

}  // namespace conformesh::intrinsic::detail
