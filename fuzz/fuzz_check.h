// fuzz_check.h — what the three reader fuzz targets assert about any input: the reader either throws InputError or
// returns a MeshData whose indices, array lengths and numbers are all valid; and such a MeshData, written as PLY in
// each encoding (and as OBJ/OFF when it has positions), reads back identical bit for bit without any error.
//
// A violated property calls abort() after printing what differed, so libFuzzer records the input as a crash.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "io/mesh_io_internal.h"

namespace conformesh::fuzz {

using intrinsic::MeshData;

[[noreturn]] inline void violated(const char* what) {
  std::fprintf(stderr, "fuzz property violated: %s\n", what);
  std::abort();
}

inline bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Invariants of every MeshData a reader returns.
inline void checkMeshData(const MeshData& m) {
  if (m.nVertices < 0) violated("negative nVertices");
  if (m.faces.empty()) violated("no faces returned without an error");
  if (!m.positions.empty() && static_cast<long long>(m.positions.size()) != m.nVertices)
    violated("positions size differs from nVertices");
  for (const auto& p : m.positions)
    if (!p.allFinite()) violated("non-finite position");
  for (const auto& f : m.faces)
    for (int v : f)
      if (v < 0 || v >= m.nVertices) violated("face index out of range");
  for (const auto& e : m.edges)
    if (e.v0 < 0 || e.v0 >= m.nVertices || e.v1 < 0 || e.v1 >= m.nVertices || !std::isfinite(e.length) ||
        !(e.length > 0))
      violated("bad edge record");
  if (!m.cornerEdges.empty() && m.cornerEdges.size() != m.faces.size()) violated("cornerEdges size");
  for (const auto& c : m.cornerEdges)
    for (int e : c)
      if (e < 0 || e >= static_cast<long long>(m.edges.size())) violated("cornerEdges index out of range");
  for (const auto& [name, values] : m.vertexProperties)
    if (static_cast<long long>(values.size()) != m.nVertices) violated("vertex property size");
  for (const auto& [name, values] : m.edgeProperties)
    if (values.size() != m.edges.size()) violated("edge property size");
}

inline void requireSame(const MeshData& a, const MeshData& b, bool full) {
  if (a.nVertices != b.nVertices) violated("round trip: nVertices");
  if (a.faces != b.faces) violated("round trip: faces");
  if (a.background != b.background) violated("round trip: background");
  if (a.comments != b.comments) violated("round trip: comments");
  if (a.positions.size() != b.positions.size()) violated("round trip: positions size");
  for (std::size_t v = 0; v < a.positions.size(); ++v)
    for (int k = 0; k < 3; ++k)
      if (!sameBits(a.positions[v][k], b.positions[v][k])) violated("round trip: position bits");
  if (!full) return;
  if (a.cornerEdges != b.cornerEdges) violated("round trip: cornerEdges");
  if (a.edges.size() != b.edges.size()) violated("round trip: edges size");
  for (std::size_t e = 0; e < a.edges.size(); ++e)
    if (a.edges[e].v0 != b.edges[e].v0 || a.edges[e].v1 != b.edges[e].v1 ||
        !sameBits(a.edges[e].length, b.edges[e].length))
      violated("round trip: edge record");
  if (a.vertexProperties.size() != b.vertexProperties.size() || a.edgeProperties.size() != b.edgeProperties.size())
    violated("round trip: property names");
  for (const auto* pa : {&a.vertexProperties, &a.edgeProperties}) {
    const auto& pb = pa == &a.vertexProperties ? b.vertexProperties : b.edgeProperties;
    for (const auto& [name, values] : *pa) {
      const auto it = pb.find(name);
      if (it == pb.end() || it->second.size() != values.size()) violated("round trip: property missing");
      for (std::size_t i = 0; i < values.size(); ++i)
        if (!sameBits(values[i], it->second[i])) violated("round trip: property bits");
    }
  }
}

// Parses with `parse`; on success checks the invariants and the write/read round trips.
template <class Parse>
void fuzzOne(const unsigned char* data, std::size_t size, Parse parse) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  MeshData m;
  try {
    m = parse(bytes);
  } catch (const InputError&) {
    return;  // the expected outcome for most inputs; anything else escapes and crashes the fuzzer
  }
  checkMeshData(m);
  try {
    intrinsic::detail::validateForWriting(m, "fuzz", false);
  } catch (const InputError&) {
    return;  // e.g. a comment with a carriage return inside cannot be written faithfully
  }
  using intrinsic::PlyEncoding;
  for (const PlyEncoding enc : {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian})
    requireSame(m, intrinsic::parsePly(intrinsic::detail::serializePly(m, enc), "roundtrip.ply"), true);
  if (!m.positions.empty()) {
    requireSame(m, intrinsic::parseObj(intrinsic::detail::serializeObj(m), "roundtrip.obj"), false);
    requireSame(m, intrinsic::parseOff(intrinsic::detail::serializeOff(m), "roundtrip.off"), false);
  }
}

}  // namespace conformesh::fuzz
