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

// The steps of toTriangulation over their shared state: the file's content, the vertex compaction (in the report) and
// the triangulation being built.
class TriangulationBuilder {
 public:
  explicit TriangulationBuilder(const MeshData& data) : data_(data), src_(data.source) {}

  IntrinsicTriangulation run(ConversionReport* reportOut) {
    checkSizes();
    compactVertices();
    connect();
    if (!data_.edges.empty()) {
      if (!data_.cornerEdges.empty())
        lengthsFromEdgeIds();
      else
        lengthsFromEdgePairs();
    } else {
      lengthsFromPositions();
    }
    validateLengths(tri_, src_);
    report_.polygonsTriangulated = data_.polygonsTriangulated, report_.stripTriangles = data_.stripTriangles;
    if (reportOut) *reportOut = std::move(report_);
    return std::move(tri_);
  }

 private:
  void checkSizes() const {
    if (data_.nVertices <= 0 || data_.faces.empty()) throw InputError(describeAt(src_, "the mesh has no faces"));
    if (!data_.positions.empty() && static_cast<int>(data_.positions.size()) != data_.nVertices)
      throw InputError(describeAt(src_, "expected " + std::to_string(data_.nVertices) + " vertex positions, found " +
                                            std::to_string(data_.positions.size())));
  }

  // Compact away vertices that no face uses (OBJ files often carry them); they have no intrinsic meaning.
  void compactVertices() {
    used_.assign(data_.nVertices, 0);
    for (size_t f = 0; f < data_.faces.size(); ++f)
      for (int v : data_.faces[f])
        if (v < 0 || v >= data_.nVertices)
          throw InputError(describeAt(src_, "face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                                                " out of range [0, " + std::to_string(data_.nVertices) + ")"));
        else
          used_[v] = 1;
    report_.vertexMap.assign(data_.nVertices, kInvalid);
    n_ = 0;
    for (int v = 0; v < data_.nVertices; ++v)
      if (used_[v]) report_.vertexMap[v] = n_++;
    report_.unreferencedVerticesRemoved = data_.nVertices - n_;
  }

  void connect() {
    std::vector<std::array<int, 3>> faces = data_.faces;
    if (n_ != data_.nVertices)
      for (auto& f : faces)
        for (int& v : f) v = report_.vertexMap[v];
    tri_.background = data_.background;
    tri_.mesh = HalfedgeMesh::fromFaces(faces, n_, src_, &report_.build, data_.cornerEdges);
    tri_.edgeLengths.assign(tri_.mesh.nEdges(), 0.0);
  }

  void checkLength(size_t record, double l) const {
    if (!std::isfinite(l) || !(l > 0))
      throw InputError(describeAt(src_, "edge " + std::to_string(record) + " (" +
                                            std::to_string(data_.edges[record].v0) + ", " +
                                            std::to_string(data_.edges[record].v1) + ") has length " + formatNumber(l) +
                                            "; lengths must be finite and positive"));
  }

  // Input vertex index of each compacted vertex.
  std::vector<int> originalIndices() const {
    std::vector<int> original(n_);
    for (int v = 0; v < data_.nVertices; ++v)
      if (report_.vertexMap[v] != kInvalid) original[report_.vertexMap[v]] = v;
    return original;
  }

  // Δ-complex: mesh edge ids are the records' indices (HalfedgeMesh groups halfedges by corner edge id).
  void lengthsFromEdgeIds() {
    const HalfedgeMesh& m = tri_.mesh;
    if (static_cast<int>(data_.edges.size()) != m.nEdges())
      throw InputError(describeAt(src_, "the faces use " + std::to_string(m.nEdges()) +
                                            " edges but the edge "
                                            "element lists " +
                                            std::to_string(data_.edges.size())));
    for (int e = 0; e < m.nEdges(); ++e) {
      const EdgeRecord& r = data_.edges[e];
      const int h = m.edgeHalfedge(e);
      const int a = r.v0 >= 0 && r.v0 < data_.nVertices ? report_.vertexMap[r.v0] : kInvalid;
      const int b = r.v1 >= 0 && r.v1 < data_.nVertices ? report_.vertexMap[r.v1] : kInvalid;
      if (pairKey(a, b) != pairKey(m.tail(h), m.tip(h)) || a == kInvalid || b == kInvalid)
        throw InputError(describeAt(src_, "edge " + std::to_string(e) + " is listed as (" + std::to_string(r.v0) +
                                              ", " + std::to_string(r.v1) +
                                              ") but the faces' edge_index makes it "
                                              "join other vertices"));
      checkLength(e, r.length);
      tri_.edgeLengths[e] = r.length;
    }
  }

  // Polygon soup: at most one edge per vertex pair, so the pair identifies the edge.
  void lengthsFromEdgePairs() {
    std::unordered_map<std::uint64_t, int> recordOf;
    recordOf.reserve(2 * data_.edges.size());
    for (size_t i = 0; i < data_.edges.size(); ++i) {
      const EdgeRecord& r = data_.edges[i];
      if (r.v0 < 0 || r.v0 >= data_.nVertices || r.v1 < 0 || r.v1 >= data_.nVertices || r.v0 == r.v1)
        throw InputError(describeAt(src_, "edge " + std::to_string(i) + " (" + std::to_string(r.v0) + ", " +
                                              std::to_string(r.v1) + ") does not join two distinct vertices in [0, " +
                                              std::to_string(data_.nVertices) + ")"));
      checkLength(i, r.length);
      if (!recordOf.emplace(pairKey(r.v0, r.v1), static_cast<int>(i)).second)
        throw InputError(describeAt(src_, "edge " + std::to_string(i) + " (" + std::to_string(r.v0) + ", " +
                                              std::to_string(r.v1) +
                                              ") is listed twice; a mesh with several edges "
                                              "between two vertices needs the face property edge_index"));
    }
    // Edge records are in input vertex numbering; look them up with the original indices.
    const std::vector<int> original = originalIndices();
    const HalfedgeMesh& m = tri_.mesh;
    std::vector<char> recordUsed(data_.edges.size(), 0);
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e);
      const int a = original[m.tail(h)], b = original[m.tip(h)];
      const auto it = recordOf.find(pairKey(a, b));
      if (it == recordOf.end())
        throw InputError(describeAt(src_, "edge (" + std::to_string(a) + ", " + std::to_string(b) + ") of face " +
                                              std::to_string(h / 3) + " has no length in the edge element"));
      tri_.edgeLengths[e] = data_.edges[it->second].length;
      recordUsed[it->second] = 1;
    }
    for (size_t i = 0; i < data_.edges.size(); ++i)
      if (!recordUsed[i])
        throw InputError(describeAt(src_, "edge " + std::to_string(i) + " (" + std::to_string(data_.edges[i].v0) +
                                              ", " + std::to_string(data_.edges[i].v1) +
                                              ") is not a side of any face"));
  }

  void lengthsFromPositions() {
    if (data_.positions.empty())
      throw InputError(describeAt(src_, "the mesh has neither vertex positions nor an edge element with lengths"));
    for (int v = 0; v < data_.nVertices; ++v)
      if (used_[v] && !data_.positions[v].allFinite())
        throw InputError(describeAt(src_, "vertex " + std::to_string(v) + " has a non-finite coordinate (" +
                                              formatNumber(data_.positions[v].x()) + ", " +
                                              formatNumber(data_.positions[v].y()) + ", " +
                                              formatNumber(data_.positions[v].z()) + ")"));
    const std::vector<int> original = originalIndices();
    const HalfedgeMesh& m = tri_.mesh;
    for (int e = 0; e < m.nEdges(); ++e) {
      const int h = m.edgeHalfedge(e);
      tri_.edgeLengths[e] = (data_.positions[original[m.tail(h)]] - data_.positions[original[m.tip(h)]]).norm();
    }
    report_.lengthsFromPositions = true;
  }

  const MeshData& data_;
  const std::string& src_;
  ConversionReport report_;
  IntrinsicTriangulation tri_;
  std::vector<char> used_;
  int n_ = 0;  // vertices after compaction
};

}  // namespace

IntrinsicTriangulation toTriangulation(const MeshData& data, ConversionReport* reportOut) {
  return TriangulationBuilder(data).run(reportOut);
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
