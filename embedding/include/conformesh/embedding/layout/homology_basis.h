// homology_basis.h — a system of 2g generator loops of a closed triangulated surface by the tree–cotree decomposition
// (Eppstein 2003; with the greedy weights of Erickson–Whittlesey 2005, which make the loops short), and the single
// relation that the 2g loops satisfy, read off from the cut.
//
// Every edge falls in exactly one of: the primal tree T (a shortest-path spanning tree of the vertices, Boost.Graph
// Dijkstra), the cotree C (a spanning tree of the faces through edges not in T, Boost.Graph Kruskal), or the 2g
// leftover generator edges G (Euler: E = (V − 1) + (F − 1) + 2g). Cutting along T ∪ G leaves the faces glued along C:
// a topological disk, the fundamental domain that fundamental_domain.h develops. docs/layout.md §1 explains it.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::embedding {

// A word in the free group on the generators: letter +(i+1) is generator i, −(i+1) its inverse.
using GroupWord = std::vector<int>;

enum class EdgeClass : char { Tree, Cotree, Generator };

struct HomologyBasis {
  int genus = 0;
  int rootVertex = 0;                // root of the primal tree T
  int rootFace = 0;                  // root of the cotree C
  std::vector<EdgeClass> edgeClass;  // per edge
  std::vector<int> generatorEdges;   // the 2g edges of G, in generator order
  std::vector<int> parentHalfedge;   // per vertex: halfedge of T arriving at it from its parent (kInvalid at root)
  std::vector<double> rootDistance;  // per vertex: length of its T-path to the root
  // Per halfedge h not in C, the deck transformation of crossing h (fundamental_domain.h: A_h) as a word in the
  // generators; empty for cotree halfedges. The generator edge i's halfedge edgeHalfedge(e) has the word [+(i+1)].
  std::vector<GroupWord> crossingWord;
  // The surface-group relation: the cyclically reduced product, around the root vertex, of the crossing words. For a
  // closed orientable surface it has length 4g and contains each generator once with each sign.
  GroupWord relation;
};

// Tree–cotree decomposition of a closed connected triangulation (lengths weight the trees: T is the shortest-path
// tree from `rootVertex`, C the maximum spanning tree of the dual graph for the weight d(tail) + ℓ + d(tip) of the
// primal loop each non-tree edge closes, so that G's loops are the greedy shortest system). Throws InputError for a
// surface with boundary or more than one component.
HomologyBasis treeCotree(const intrinsic::IntrinsicTriangulation& tri, int rootVertex = 0);

// The primal loop of generator i as a closed sequence of halfedges: the T-path from the root to the generator edge's
// tail, the generator halfedge edgeHalfedge(e), and the T-path back to the root.
std::vector<int> generatorLoop(const intrinsic::IntrinsicTriangulation& tri, const HomologyBasis& basis, int i);

// "a1 b1 A1 B1"-style text of a word (generators named g1, g2, ...; inverses with a ⁻¹ suffix written as "^-1").
std::string toString(const GroupWord& word);

// Free and cyclic reduction helpers (used for the relation, exposed for tests).
GroupWord freeReduce(const GroupWord& word);
GroupWord inverse(const GroupWord& word);

}  // namespace conformesh::embedding
