// halfedge_mesh.h — connectivity of a triangulated surface as a halfedge Δ-complex in flat arrays.
//
// Only combinatorics live here: no lengths, no positions. Intrinsic edge flips and vertex insertions create several
// edges between the same two vertices and self-loops, so nothing in conformesh may look an edge up by its endpoint
// pair; the only place endpoint pairs are matched is the construction from a polygon soup (`fromFaces` without edge
// ids), where the input by definition has at most one edge per vertex pair.
//
// Halfedges are implicit: halfedge h = 3f + k is corner k of face f and runs from faceVertex(f, k) to
// faceVertex(f, k + 1). next/prev/face are arithmetic; twin, edge and tail are stored (12 bytes per halfedge).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace conformesh::intrinsic {

constexpr int kInvalid = -1;

// Where the elements that survive a removal now live (HalfedgeMesh::removeDegree3Vertex). Removal compacts the arrays
// by swap-with-last, so indices stay dense and every loop over 0..n−1 sees live elements only; the price is that a few
// elements change index, listed here as (old index, new index) pairs, to be applied to per-element data with
// applyMoves. Halfedge moves include the three halfedges of the merged face.
struct ElementMoves {
  std::vector<std::pair<int, int>> vertices, edges, faces, halfedges;
};

// Applies `moves` (old index → new index, all at once) to per-element data and shrinks it to `newSize`.
template <class T>
void applyMoves(std::vector<T>& data, const std::vector<std::pair<int, int>>& moves, int newSize) {
  std::vector<T> values;
  values.reserve(moves.size());
  for (const auto& m : moves) values.push_back(data[m.first]);
  for (size_t i = 0; i < moves.size(); ++i) data[moves[i].second] = values[i];
  data.resize(newSize);
}

// Topology of one connected component.
struct ComponentTopology {
  int vertices = 0, edges = 0, faces = 0;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;  // V - E + F
  int genus = 0;                // from chi = 2 - 2g - b
};

// What building the connectivity found and fixed.
struct BuildReport {
  int reorientedFaces = 0;  // faces whose orientation was flipped to agree with their neighbours
};

class HalfedgeMesh {
 public:
  HalfedgeMesh() = default;

  // Builds the connectivity of `faces` over vertices 0..nVertices-1 and validates it. Throws InputError naming
  // `source` and the offending element for: an index out of range, a face repeating a vertex, an edge in more than two
  // faces, a pinched vertex (its faces form more than one fan), a vertex in no face, and a non-orientable component.
  // Orientable components whose faces disagree are reoriented (reported in `report`).
  //
  // `cornerEdgeIds`, if not empty, gives for each corner k of face f the id of edge (f,k)->(f,k+1); halfedges with the
  // same id are glued. This is how Δ-complexes with multi-edges and self-loops round-trip through files. Without it,
  // halfedges are glued by their endpoint pairs.
  static HalfedgeMesh fromFaces(const std::vector<std::array<int, 3>>& faces, int nVertices,
                                const std::string& source = "", BuildReport* report = nullptr,
                                const std::vector<std::array<int, 3>>& cornerEdgeIds = {});

  // === sizes
  int nVertices() const { return static_cast<int>(vertexHalfedge_.size()); }
  int nFaces() const { return static_cast<int>(tail_.size() / 3); }
  int nHalfedges() const { return static_cast<int>(tail_.size()); }
  int nEdges() const { return static_cast<int>(edgeHalfedge_.size()); }

  // === halfedge navigation
  static int face(int h) { return h / 3; }
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  static int halfedge(int f, int k) { return 3 * f + k; }
  int twin(int h) const { return twin_[h]; }  // kInvalid on the boundary
  int tail(int h) const { return tail_[h]; }
  int tip(int h) const { return tail_[next(h)]; }
  int edge(int h) const { return edge_[h]; }
  int faceVertex(int f, int k) const { return tail_[3 * f + k]; }

  // An interior halfedge of edge e (the only one if e is a boundary edge).
  int edgeHalfedge(int e) const { return edgeHalfedge_[e]; }
  bool isBoundaryEdge(int e) const { return twin_[edgeHalfedge_[e]] == kInvalid; }

  // An outgoing halfedge of v. For a boundary vertex it is the outgoing boundary halfedge, so that rotating with
  // nextOutgoing() from it sweeps the whole fan and stops at the boundary.
  int vertexHalfedge(int v) const { return vertexHalfedge_[v]; }
  bool isBoundaryVertex(int v) const { return twin_[vertexHalfedge_[v]] == kInvalid; }
  // The next outgoing halfedge around tail(h), across edge(prev(h)); kInvalid when that edge is a boundary edge.
  int nextOutgoing(int h) const { return twin_[prev(h)]; }
  // Number of faces around v (corners at v).
  int vertexDegree(int v) const;

  // The boundary halfedge that follows boundary halfedge h along its loop (both have twin == kInvalid).
  int nextBoundaryHalfedge(int h) const;

  // === topology
  std::vector<ComponentTopology> components() const;
  // Per face, the index of its connected component (faces joined across interior edges), numbered in the order of
  // components(): breadth-first from the smallest unlabelled face.
  std::vector<int> faceComponents() const;
  int eulerCharacteristic() const { return nVertices() - nEdges() + nFaces(); }
  // Each boundary loop as its list of boundary halfedges, in order.
  std::vector<std::vector<int>> boundaryLoops() const;

  // === mutation
  // Flips interior edge e: the two triangles (a,b,c) and (b,a,d) sharing it become (d,c,a) and (c,d,b), and e now
  // joins c and d. Halfedge indices of the two faces are reassigned; edge indices are stable. Returns false (and
  // changes nothing) for a boundary edge or an edge whose two sides lie in the same face. Geometric admissibility is
  // the caller's business (see intrinsic_flips.h).
  bool flip(int e);

  // Inserts a new vertex p inside face f = (a, b, c), splitting it into f = (a, b, p), (b, c, p) and (c, a, p), the two
  // new faces appended in that order. Returns p. The three new edges p-a, p-b, p-c are appended in that order.
  int splitFace(int f);

  // Inserts a new vertex on edge e, splitting e and its one or two faces. Returns the new vertex, or kInvalid (changing
  // nothing) when both sides of e lie in the same face (a Δ-complex face folded onto itself). Edge e keeps the half
  // starting at tail(edgeHalfedge(e)); the other half and the new interior edges are appended: interior e gives new
  // edges [p-tip, p-c, p-d], boundary e gives [p-tip, p-c], where c (d) is the vertex opposite e in the face of
  // edgeHalfedge(e) (of its twin).
  int splitEdge(int e);

  // Removes interior vertex v of degree 3 with three distinct edges (no self-loop): its faces (v, a, b), (v, b, c),
  // (v, c, a) become the one face (a, b, c) made of their three outer halfedges, and v, its three edges and two of the
  // faces are deleted. Returns false (changing nothing) for a boundary vertex, degree ≠ 3 or a self-loop at v. The
  // last vertex, edges and faces move into the freed slots (`moves`); `mergedFace` receives the new face's index.
  // Lengths are the caller's business: the merged face keeps its three outer edges, so they need no new length.
  bool removeDegree3Vertex(int v, ElementMoves& moves, int& mergedFace);

  // Checks every invariant (twins symmetric, edges consistent, fans closed); throws std::logic_error on violation.
  // For tests and debugging: O(n).
  void checkInvariants() const;

 private:
  std::vector<int> tail_, twin_, edge_;  // per halfedge
  std::vector<int> edgeHalfedge_;        // per edge
  std::vector<int> vertexHalfedge_;      // per vertex
};

}  // namespace conformesh::intrinsic
