// mesh_io.h — reading and writing OBJ, OFF and PLY (ASCII, binary little- and big-endian) as MeshData.
//
// Readers never crash or hang on bad bytes: every problem is an InputError "FILE:LINE: what was expected, what was
// found" (or "FILE: element N: ..." for binary data). docs/formats.md documents what is read and written, including
// the metric-only PLY (an `edge` element with `vertex1 vertex2 length`, no positions) and the `comment geometry ...`
// header line.
#pragma once

#include <string>

#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::intrinsic {

enum class MeshFormat { Obj, Off, Ply };
enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

// From the file extension (case-insensitive .obj/.off/.ply); throws InputError otherwise.
MeshFormat formatFromPath(const std::string& path);

// Parses from memory; `source` names the data in error messages (and becomes MeshData::source). These are what the
// fuzz targets call. A file without faces is an error. Polygons are fan-triangulated from their first corner
// (MeshData::polygonsTriangulated; positions are not used, so a non-convex polygon may fold); PLY `tristrips` are
// unrolled (MeshData::stripTriangles).
// Coordinates, lengths and properties must be finite, lengths positive, indices in range; a triangle may repeat a
// vertex only in a PLY Δ-complex (face property edge_index). Element counts are checked against the bytes that remain
// before anything is allocated. Connectivity (manifoldness, orientation) is left to toTriangulation().
struct ReadOptions {
  // Keep triangles that repeat a vertex (a degenerate face, or a polygon's fan triangle next to a repeated corner)
  // instead of refusing the file, for repairMesh (mesh/mesh_repair.h) to drop. Default: refused, and the error says
  // that `--repair` drops such faces.
  bool keepDegenerateFaces = false;
};
MeshData parseObj(const std::string& bytes, const std::string& source, const ReadOptions& options = {});
MeshData parseOff(const std::string& bytes, const std::string& source, const ReadOptions& options = {});
MeshData parsePly(const std::string& bytes, const std::string& source, const ReadOptions& options = {});

// Reads a file by extension. Throws InputError for a missing/unreadable file too.
MeshData readMesh(const std::string& path, const ReadOptions& options = {});

struct WriteOptions {
  PlyEncoding plyEncoding = PlyEncoding::BinaryLittleEndian;
};
// Writes by extension. OBJ and OFF need positions (they cannot carry lengths): writing a metric-only mesh to them is an
// InputError; they also drop properties and lengths. PLY always carries the edge element with lengths when `edges` is
// non-empty, edge_index when `cornerEdges` is, positions when present, every property (as double) and the comments;
// every format gets the `geometry` line. Numbers are written exactly (shortest round-trip decimal in text, raw bytes in
// binary), so whatever the format carries reads back bit for bit. `data` is validated first (indices, array
// lengths, finite numbers, positive lengths), each problem an InputError naming `path` and the element. The file is
// written to a temporary name beside `path` and renamed, so a failed write never clobbers an existing file.
void writeMesh(const MeshData& data, const std::string& path, const WriteOptions& options = {});

}  // namespace conformesh::intrinsic
