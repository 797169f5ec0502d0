// mesh_io.h — reading and writing OBJ, OFF and PLY (ASCII, binary little- and big-endian) as MeshData.
//
// Readers never crash or hang on bad bytes: every problem is an InputError "FILE:LINE: what was expected, what was
// found" (or "FILE: element N: ..." for binary data). docs/formats.md documents what is read and written, including
// the metric-only PLY (an `edge` element with `vertex1 vertex2 length`, no positions) and the `comment geometry ...`
// header line.
#pragma once

#include <string>

#include "conformesh/intrinsic/mesh_data.h"

namespace conformesh::intrinsic {

enum class MeshFormat { Obj, Off, Ply };
enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

// From the file extension (case-insensitive .obj/.off/.ply); throws InputError otherwise.
MeshFormat formatFromPath(const std::string& path);

// Parses from memory; `source` names the data in error messages. These are what the fuzz targets call.
MeshData parseObj(const std::string& bytes, const std::string& source);
MeshData parseOff(const std::string& bytes, const std::string& source);
MeshData parsePly(const std::string& bytes, const std::string& source);

// Reads a file by extension. Throws InputError for a missing/unreadable file too.
MeshData readMesh(const std::string& path);

struct WriteOptions {
  PlyEncoding plyEncoding = PlyEncoding::BinaryLittleEndian;
};
// Writes by extension. OBJ and OFF need positions (they cannot carry lengths): writing a metric-only mesh to them is an
// InputError. PLY always carries the edge element with lengths when `edges` is non-empty. The file is written to a
// temporary name and renamed, so a failed write never clobbers an existing file.
void writeMesh(const MeshData& data, const std::string& path, const WriteOptions& options = {});

}  // namespace conformesh::intrinsic
