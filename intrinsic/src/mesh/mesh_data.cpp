// mesh_data.cpp — MeshData (a file's content) to IntrinsicTriangulation and back: vertex compaction, connectivity,
// and edge lengths from an edge element or from positions, each value checked and every failure named.
#include "conformesh/intrinsic/mesh/mesh_data.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

std::uint64_t pairKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

}  // namespace

IntrinsicTriangulation toTriangulation(const MeshData& data, ConversionReport* reportOut) {
  ConversionReport report;
  const std::string& src = data.source;
  if (data.nVertices <= 0 || data.faces.empty()) throw InputError(describeAt(src, "the mesh has no faces"));
  if (!data.positions.empty() && static_cast<int>(data.positions.size()) != data.nVertices)
    throw InputError(describeAt(src, "expected " + std::to_string(data.nVertices) + " vertex positions, found " +
                                         std::to_string(data.positions.size())));

  // --- compact away vertices that no face uses (OBJ files often carry them); they have no intrinsic meaning.
  std::vector<char> used(data.nVertices, 0);
  for (size_t f = 0; f < data.faces.size(); ++f)
    for (int v : data.faces[f])
      if (v < 0 || v >= data.nVertices)
        throw InputError(describeAt(src, "face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                                             " out of range [0, " + std::to_string(data.nVertices) + ")"));
      else
        used[v] = 1;
  report.vertexMap.assign(data.nVertices, kInvalid);
  int n = 0;
  for (int v = 0; v < data.nVertices; ++v)
    if (used[v]) report.vertexMap[v] = n++;
  report.unreferencedVerticesRemoved = data.nVertices - n;
  std::vector<std::array<int, 3>> faces = data.faces;
  if (n != data.nVertices)
    for (auto& f : faces)
      for (int& v : f) v = report.vertexMap[v];

  IntrinsicTriangulation tri;
  tri.background = data.background;
  tri.mesh = HalfedgeMesh::fromFaces(faces, n, src, &report.build, data.cornerEdges);
  const HalfedgeMesh& m = tri.mesh;
  tri.edgeLengths.assign(m.nEdges(), 0.0);

  auto checkLength = [&](size_t record, double l) {
    if (!std::isfinite(l) || !(l > 0))
      throw InputError(describeAt(src, "edge " + std::to_string(record) + " (" + std::to_string(data.edges[record].v0) +
                                           ", " + std::to_string(data.edges[record].v1) + ") has length " +
                                           formatNumber(l) + "; lengths must be finite and positive"));
  };

  if (!data.edges.empty()) {
    if (!data.cornerEdges.empty()) {
      // Δ-complex: mesh edge ids are the records' indices (HalfedgeMesh groups halfedges by corner edge id).
      if (static_cast<int>(data.edges.size()) != m.nEdges())
        throw InputError(describeAt(src, "the faces use " + std::to_string(m.nEdges()) +
                                             " edges but the edge "
                                             "element lists " +
                                             std::to_string(data.edges.size())));
      for (int e = 0; e < m.nEdges(); ++e) {
        const EdgeRecord& r = data.edges[e];
        const int h = m.edgeHalfedge(e);
        const int a = r.v0 >= 0 && r.v0 < data.nVertices ? report.vertexMap[r.v0] : kInvalid;
        const int b = r.v1 >= 0 && r.v1 < data.nVertices ? report.vertexMap[r.v1] : kInvalid;
        if (pairKey(a, b) != pairKey(m.tail(h), m.tip(h)) || a == kInvalid || b == kInvalid)
          throw InputError(describeAt(src, "edge " + std::to_string(e) + " is listed as (" + std::to_string(r.v0) +
                                               ", " + std::to_string(r.v1) +
                                               ") but the faces' edge_index makes it "
                                               "join other vertices"));
        checkLength(e, r.length);
        tri.edgeLengths[e] = r.length;
      }
    } else {
      // Polygon soup: at most one edge per vertex pair, so the pair identifies the edge.
      std::unordered_map<std::uint64_t, int> recordOf;
      recordOf.reserve(2 * data.edges.size());
      for (size_t i = 0; i < data.edges.size(); ++i) {
        const EdgeRecord& r = data.edges[i];
        if (r.v0 < 0 || r.v0 >= data.nVertices || r.v1 < 0 || r.v1 >= data.nVertices || r.v0 == r.v1)
          throw InputError(describeAt(src, "edge " + std::to_string(i) + " (" + std::to_string(r.v0) + ", " +
                                               std::to_string(r.v1) + ") does not join two distinct vertices in [0, " +
                                               std::to_string(data.nVertices) + ")"));
        checkLength(i, r.length);
        if (!recordOf.emplace(pairKey(r.v0, r.v1), static_cast<int>(i)).second)
          throw InputError(describeAt(src, "edge " + std::to_string(i) + " (" + std::to_string(r.v0) + ", " +
                                               std::to_string(r.v1) +
                                               ") is listed twice; a mesh with several edges "
                                               "between two vertices needs the face property edge_index"));
      }
      // Edge records are in input vertex numbering; look them up with the original indices.
      std::vector<int> original(n);
      for (int v = 0; v < data.nVertices; ++v)
        if (report.vertexMap[v] != kInvalid) original[report.vertexMap[v]] = v;
      std::vector<char> recordUsed(data.edges.size(), 0);
      for (int e = 0; e < m.nEdges(); ++e) {
        const int h = m.edgeHalfedge(e);
        const int a = original[m.tail(h)], b = original[m.tip(h)];
        const auto it = recordOf.find(pairKey(a, b));
        if (it == recordOf.end())
          throw InputError(describeAt(src, "edge (" + std::to_string(a) + ", " + std::to_string(b) + ") of face " +
                                               std::to_string(h / 3) + " has no length in the edge element"));
        tri.edgeLengths[e] = data.edges[it->second].length;
        recordUsed[it->second] = 1;
      }
      for (size_t i = 0; i < data.edges.size(); ++i)
        if (!recordUsed[i])
          throw InputError(describeAt(src, "edge " + std::to_string(i) + " (" + std::to_string(data.edges[i].v0) +
                                               ", " + std::to_string(data.edges[i].v1) +
                                               ") is not a side of any face"));
    }
  } else {
    if (data.positions.empty())
      throw InputError(describeAt(src, "the mesh has neither vertex positions nor an edge element with lengths"));
    for (int v = 0; v < data.nVertices; ++v)
      if (used[v] && !data.positions[v].allFinite())
        throw InputError(describeAt(src, "vertex " + std::to_string(v) + " has a non-finite coordinate (" +
                                             formatNumber(data.positions[v].x()) + ", " +
                                             formatNumber(data.positions[v].y()) + ", " +
                                             formatNumber(data.positions[v].z()) + ")"));
    std::vector<int> original(n);
    for (int v = 0; v < data.nVertices; ++v)
      if (report.vertexMap[v] != kInvalid) original[report.vertexMap[v]] = v;
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e);
      tri.edgeLengths[e] = (data.positions[original[m.tail(h)]] - data.positions[original[m.tip(h)]]).norm();
    }
    report.lengthsFromPositions = true;
  }
  validateLengths(tri, src);
  if (reportOut) *reportOut = std::move(report);
  return tri;
}

MeshData fromTriangulation(const IntrinsicTriangulation& tri) {
  const HalfedgeMesh& m = tri.mesh;
  MeshData d;
  d.nVertices = m.nVertices();
  d.background = tri.background;
  d.faces.resize(m.nFaces());
  for (int f = 0; f < m.nFaces(); ++f) d.faces[f] = {m.faceVertex(f, 0), m.faceVertex(f, 1), m.faceVertex(f, 2)};
  d.edges.resize(m.nEdges());
  std::vector<std::uint64_t> keys(m.nEdges());
  bool selfLoop = false;
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    d.edges[e] = {m.tail(h), m.tip(h), tri.edgeLengths[e]};
    keys[e] = pairKey(m.tail(h), m.tip(h));
    selfLoop = selfLoop || m.tail(h) == m.tip(h);
  }
  std::sort(keys.begin(), keys.end());
  const bool multiEdge = std::adjacent_find(keys.begin(), keys.end()) != keys.end();
  if (selfLoop || multiEdge) {
    d.cornerEdges.resize(m.nFaces());
    for (int f = 0; f < m.nFaces(); ++f) d.cornerEdges[f] = {m.edge(3 * f), m.edge(3 * f + 1), m.edge(3 * f + 2)};
  }
  return d;
}

}  // namespace conformesh::intrinsic
