// homology_basis.cpp — tree–cotree decomposition with Boost.Graph (Dijkstra for the primal tree, Kruskal for the dual
// cotree) and the crossing words of the cut, obtained by pruning the primal tree from its leaves. See homology_basis.h
// and docs/layout.md §1.
#include "conformesh/embedding/layout/homology_basis.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

struct EdgeProps {
  double weight = 0;
  int index = 0;  // mesh edge
};
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, EdgeProps>;

GroupWord concat(const GroupWord& a, const GroupWord& b) {
  GroupWord out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

}  // namespace

// =====================================================================================================================
// words

GroupWord freeReduce(const GroupWord& word) {
  GroupWord out;
  for (int letter : word) {
    if (!out.empty() && out.back() == -letter)
      out.pop_back();
    else
      out.push_back(letter);
  }
  return out;
}

GroupWord inverse(const GroupWord& word) {
  GroupWord out(word.rbegin(), word.rend());
  for (int& letter : out) letter = -letter;
  return out;
}

std::string toString(const GroupWord& word) {
  if (word.empty()) return "1";
  std::ostringstream s;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (i) s << ' ';
    s << 'g' << std::abs(word[i]);
    if (word[i] < 0) s << "^-1";
  }
  return s.str();
}

// =====================================================================================================================
// tree–cotree

HomologyBasis treeCotree(const IntrinsicTriangulation& tri, int rootVertex) {
  const HalfedgeMesh& m = tri.mesh;
  const auto comps = m.components();
  if (comps.size() != 1)
    throw InputError("treeCotree: expected one connected component, found " + std::to_string(comps.size()));
  if (comps[0].boundaryLoops != 0)
    throw InputError("treeCotree: expected a closed surface, found " + std::to_string(comps[0].boundaryLoops) +
                     " boundary loop(s)");
  if (rootVertex < 0 || rootVertex >= m.nVertices())
    throw InputError("treeCotree: root vertex " + std::to_string(rootVertex) + " out of range [0, " +
                     std::to_string(m.nVertices()) + ")");
  HomologyBasis basis;
  basis.genus = comps[0].genus;
  basis.rootVertex = rootVertex;
  const int nv = m.nVertices(), ne = m.nEdges(), nf = m.nFaces();

  // --- primal shortest-path tree T (Dijkstra over the edge lengths; self-loops never improve a distance)
  Graph primal(nv);
  for (int e = 0; e < ne; ++e) {
    const int h = m.edgeHalfedge(e);
    boost::add_edge(m.tail(h), m.tip(h), EdgeProps{tri.edgeLengths[e], e}, primal);
  }
  basis.rootDistance.assign(nv, 0);
  boost::dijkstra_shortest_paths(primal, rootVertex,
                                 boost::weight_map(boost::get(&EdgeProps::weight, primal))
                                     .distance_map(boost::make_iterator_property_map(
                                         basis.rootDistance.begin(), boost::get(boost::vertex_index, primal))));
  // The tree edge into v is an edge (u, v) with d(u) + ℓ = d(v); since ℓ > 0 every such u is strictly closer to the
  // root, so the choice (the smallest residual, robust to round-off) cannot close a cycle.
  basis.parentHalfedge.assign(nv, kInvalid);
  std::vector<double> bestResidual(nv, std::numeric_limits<double>::infinity());
  for (int h = 0; h < m.nHalfedges(); ++h) {
    const int u = m.tail(h), v = m.tip(h);
    if (v == rootVertex || u == v || !(basis.rootDistance[u] < basis.rootDistance[v])) continue;
    const double residual = std::abs(basis.rootDistance[u] + tri.length(h) - basis.rootDistance[v]);
    if (residual < bestResidual[v]) {
      bestResidual[v] = residual;
      basis.parentHalfedge[v] = h;
    }
  }
  basis.edgeClass.assign(ne, EdgeClass::Generator);
  for (int v = 0; v < nv; ++v) {
    if (v == rootVertex) continue;
    if (basis.parentHalfedge[v] == kInvalid)
      throw InputError("treeCotree: vertex " + std::to_string(v) + " is not reached from the root");
    basis.edgeClass[m.edge(basis.parentHalfedge[v])] = EdgeClass::Tree;
  }

  // --- dual maximum spanning tree C over the non-tree edges (Kruskal on negated weights): the edges left out close the
  // longest primal loops last, so G holds the greedy shortest loops (Erickson–Whittlesey).
  Graph dual(nf);
  for (int e = 0; e < ne; ++e) {
    if (basis.edgeClass[e] == EdgeClass::Tree) continue;
    const int h = m.edgeHalfedge(e);
    const double loop = basis.rootDistance[m.tail(h)] + tri.edgeLengths[e] + basis.rootDistance[m.tip(h)];
    boost::add_edge(HalfedgeMesh::face(h), HalfedgeMesh::face(m.twin(h)), EdgeProps{-loop, e}, dual);
  }
  std::vector<Graph::edge_descriptor> cotree;
  boost::kruskal_minimum_spanning_tree(dual, std::back_inserter(cotree),
                                       boost::weight_map(boost::get(&EdgeProps::weight, dual)));
  for (const auto& d : cotree) basis.edgeClass[dual[d].index] = EdgeClass::Cotree;
  basis.rootFace = HalfedgeMesh::face(m.vertexHalfedge(rootVertex));
  for (int e = 0; e < ne; ++e)
    if (basis.edgeClass[e] == EdgeClass::Generator) basis.generatorEdges.push_back(e);
  if (static_cast<int>(basis.generatorEdges.size()) != 2 * basis.genus)
    throw InputError("treeCotree: found " + std::to_string(basis.generatorEdges.size()) +
                     " leftover edges, expected 2g = " + std::to_string(2 * basis.genus));

  // --- crossing words. Around a vertex v with outgoing halfedges h_0, h_1 = twin(prev(h_0)), ..., the crossings
  // x_i = prev(h_i) satisfy A_{x_0} A_{x_1} ⋯ A_{x_{k−1}} = 1 (the star of v closes up: angle sum 2π). Pruning T from
  // its leaves, the parent edge of each vertex is the only unknown in its relation; at the root the relation is left.
  basis.crossingWord.assign(m.nHalfedges(), {});
  for (int i = 0; i < static_cast<int>(basis.generatorEdges.size()); ++i) {
    const int h = m.edgeHalfedge(basis.generatorEdges[i]);
    basis.crossingWord[h] = {i + 1};
    basis.crossingWord[m.twin(h)] = {-(i + 1)};
  }
  auto crossingsAround = [&](int v) {
    std::vector<int> xs;
    const int h0 = m.vertexHalfedge(v);
    int h = h0;
    do {
      xs.push_back(HalfedgeMesh::prev(h));
      h = m.nextOutgoing(h);
    } while (h != h0);
    return xs;
  };
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return basis.rootDistance[a] > basis.rootDistance[b]; });  // children first
  for (int v : order) {
    if (v == rootVertex) continue;
    const std::vector<int> xs = crossingsAround(v);
    const int parentIn = basis.parentHalfedge[v];  // arrives at v: one of the x_i
    const auto it = std::find(xs.begin(), xs.end(), parentIn);
    const std::size_t j = static_cast<std::size_t>(it - xs.begin());
    GroupWord rest;
    for (std::size_t s = 1; s < xs.size(); ++s) rest = concat(rest, basis.crossingWord[xs[(j + s) % xs.size()]]);
    rest = freeReduce(rest);
    basis.crossingWord[parentIn] = inverse(rest);
    basis.crossingWord[m.twin(parentIn)] = rest;
  }
  GroupWord relation;
  for (int x : crossingsAround(rootVertex)) relation = concat(relation, basis.crossingWord[x]);
  relation = freeReduce(relation);
  while (relation.size() >= 2 && relation.front() == -relation.back()) {
    relation.pop_back();
    relation.erase(relation.begin());
  }
  basis.relation = relation;
  return basis;
}

std::vector<int> generatorLoop(const IntrinsicTriangulation& tri, const HomologyBasis& basis, int i) {
  const HalfedgeMesh& m = tri.mesh;
  if (i < 0 || i >= static_cast<int>(basis.generatorEdges.size()))
    throw InputError("generatorLoop: generator " + std::to_string(i) + " out of range [0, " +
                     std::to_string(basis.generatorEdges.size()) + ")");
  const int g = m.edgeHalfedge(basis.generatorEdges[i]);
  std::vector<int> down;  // root → tail(g), built backwards
  for (int v = m.tail(g); v != basis.rootVertex; v = m.tail(basis.parentHalfedge[v]))
    down.push_back(basis.parentHalfedge[v]);
  std::vector<int> loop(down.rbegin(), down.rend());
  loop.push_back(g);
  for (int v = m.tip(g); v != basis.rootVertex; v = m.tail(basis.parentHalfedge[v]))
    loop.push_back(m.twin(basis.parentHalfedge[v]));
  return loop;
}

}  // namespace conformesh::embedding
