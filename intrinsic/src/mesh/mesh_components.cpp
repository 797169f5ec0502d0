// mesh_components.cpp — splitting a triangulation into its connected components and concatenating file data.
#include "conformesh/intrinsic/mesh/mesh_components.h"

#include <algorithm>
#include <map>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

// The file data of one component: its faces renumbered, its edges with their lengths (and corner edges when the
// input needs them), read back by toTriangulation exactly as a file of that component alone would be.
MeshData componentData(const MeshData& whole, const MeshComponent& c) {
  std::vector<int> vertexIndex(whole.nVertices, kInvalid), edgeIndex(whole.edges.size(), kInvalid);
  for (std::size_t i = 0; i < c.vertices.size(); ++i) vertexIndex[c.vertices[i]] = static_cast<int>(i);
  MeshData d;
  d.source = whole.source;
  d.background = whole.background;
  d.nVertices = static_cast<int>(c.vertices.size());
  for (int f : c.faces) {
    const auto& face = whole.faces[f];
    d.faces.push_back({vertexIndex[face[0]], vertexIndex[face[1]], vertexIndex[face[2]]});
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      // Without corner edges, edge (k, k+1) is found by its endpoints; the edges are listed for their lengths.
      const int e = whole.cornerEdges.empty() ? kInvalid : whole.cornerEdges[f][k];
      if (e != kInvalid && edgeIndex[e] == kInvalid) {
        edgeIndex[e] = static_cast<int>(d.edges.size());
        d.edges.push_back({vertexIndex[whole.edges[e].v0], vertexIndex[whole.edges[e].v1], whole.edges[e].length});
      }
      corners[k] = e == kInvalid ? kInvalid : edgeIndex[e];
    }
    if (!whole.cornerEdges.empty()) d.cornerEdges.push_back(corners);
  }
  if (whole.cornerEdges.empty())
    for (const EdgeRecord& e : whole.edges)
      if (vertexIndex[e.v0] != kInvalid) d.edges.push_back({vertexIndex[e.v0], vertexIndex[e.v1], e.length});
  return d;
}

// Corner edges of a part whose edges are simple (no multi-edge, no loop: it has none listed), found by their
// endpoints — so that it can sit beside a part that needs them. Throws InputError for a corner with no listed edge.
std::vector<std::array<int, 3>> cornerEdgesByEndpoints(const MeshData& p) {
  std::map<std::pair<int, int>, int> byEnds;
  for (std::size_t e = 0; e < p.edges.size(); ++e)
    byEnds[std::minmax(p.edges[e].v0, p.edges[e].v1)] = static_cast<int>(e);
  std::vector<std::array<int, 3>> corners(p.faces.size());
  for (std::size_t f = 0; f < p.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto it = byEnds.find(std::minmax(p.faces[f][k], p.faces[f][(k + 1) % 3]));
      if (it == byEnds.end())
        throw InputError("concatenateMeshData: " + p.source + ": face " + std::to_string(f) +
                         " has an edge not listed");
      corners[f][k] = it->second;
    }
  return corners;
}

}  // namespace

std::vector<MeshComponent> splitComponents(const IntrinsicTriangulation& tri) {
  const HalfedgeMesh& m = tri.mesh;
  const std::vector<ComponentTopology> topology = m.components();
  std::vector<MeshComponent> out(topology.size());
  if (out.size() == 1) {
    out[0] = {tri, {}, {}, topology[0]};
    for (int v = 0; v < m.nVertices(); ++v) out[0].vertices.push_back(v);
    for (int f = 0; f < m.nFaces(); ++f) out[0].faces.push_back(f);
    return out;
  }
  const std::vector<int> comp = m.faceComponents();
  for (int f = 0; f < m.nFaces(); ++f) out[comp[f]].faces.push_back(f);
  for (int v = 0; v < m.nVertices(); ++v) out[comp[HalfedgeMesh::face(m.vertexHalfedge(v))]].vertices.push_back(v);
  const MeshData whole = fromTriangulation(tri);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].topology = topology[i];
    out[i].triangulation = toTriangulation(componentData(whole, out[i]));
  }
  return out;
}

std::string describeComponent(int index, int count, const ComponentTopology& t) {
  return "component " + std::to_string(index) + " of " + std::to_string(count) + " (" + std::to_string(t.vertices) +
         " vertices, " + std::to_string(t.faces) + " faces, genus " + std::to_string(t.genus) + ", " +
         std::to_string(t.boundaryLoops) + (t.boundaryLoops == 1 ? " boundary loop)" : " boundary loops)");
}

MeshData concatenateMeshData(const std::vector<MeshData>& parts) {
  MeshData out;
  if (parts.empty()) return out;
  out.source = parts[0].source;
  out.background = parts[0].background;
  out.comments = parts[0].comments;
  const bool positions = !parts[0].positions.empty();
  bool cornerEdges = false;
  for (const MeshData& p : parts) cornerEdges = cornerEdges || !p.cornerEdges.empty();
  std::map<std::string, std::vector<double>> vertexProps = parts[0].vertexProperties;
  for (const MeshData& p : parts)
    for (auto it = vertexProps.begin(); it != vertexProps.end();)
      it = p.vertexProperties.count(it->first) ? std::next(it) : vertexProps.erase(it);
  for (auto& [name, values] : vertexProps) values.clear();
  std::vector<double>& component = out.vertexProperties["component"];
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const MeshData& p = parts[i];
    if (p.positions.empty() == positions)
      throw InputError("concatenateMeshData: part " + std::to_string(i) + (positions ? " has no" : " has") +
                       " positions, part 0 " + (positions ? "has" : "has none"));
    const int vOffset = out.nVertices, eOffset = static_cast<int>(out.edges.size());
    for (const auto& f : p.faces) out.faces.push_back({f[0] + vOffset, f[1] + vOffset, f[2] + vOffset});
    for (const EdgeRecord& e : p.edges) out.edges.push_back({e.v0 + vOffset, e.v1 + vOffset, e.length});
    if (cornerEdges) {
      const std::vector<std::array<int, 3>> corners = p.cornerEdges.empty() ? cornerEdgesByEndpoints(p) : p.cornerEdges;
      for (const auto& c : corners) out.cornerEdges.push_back({c[0] + eOffset, c[1] + eOffset, c[2] + eOffset});
    }
    out.positions.insert(out.positions.end(), p.positions.begin(), p.positions.end());
    for (auto& [name, values] : vertexProps) {
      const std::vector<double>& v = p.vertexProperties.at(name);
      values.insert(values.end(), v.begin(), v.end());
    }
    component.insert(component.end(), p.nVertices, static_cast<double>(i));
    out.nVertices += p.nVertices;
  }
  for (auto& [name, values] : vertexProps) out.vertexProperties[name] = std::move(values);
  return out;
}

}  // namespace conformesh::intrinsic
