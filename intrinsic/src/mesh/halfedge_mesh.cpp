// halfedge_mesh.cpp — construction and validation of the halfedge Δ-complex, topology queries, and the connectivity
// operations intrinsic algorithms need (flip, face split, edge split). See halfedge_mesh.h for the conventions.
#include "conformesh/intrinsic/mesh/halfedge_mesh.h"

#include <algorithm>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <string>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

std::string faceString(const std::array<int, 3>& f) {
  return "(" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + ")";
}

// Groups halfedges that must be glued into edges. Halfedges are bucketed by their smaller endpoint (counting sort, so
// O(n) and no hashing), then matched by the larger endpoint within each bucket. `groupOf[h]` receives a group id and
// `groups` the CSR layout of members. When explicit corner edge ids are given, those ids are the groups.
struct EdgeGroups {
  std::vector<int> start;    // size nGroups + 1
  std::vector<int> members;  // halfedges, grouped
};

EdgeGroups groupByEndpoints(const std::vector<int>& tail, int nVertices) {
  const int nH = static_cast<int>(tail.size());
  auto tip = [&](int h) { return tail[HalfedgeMesh::next(h)]; };
  std::vector<int> bucketStart(nVertices + 1, 0);
  for (int h = 0; h < nH; ++h) ++bucketStart[std::min(tail[h], tip(h)) + 1];
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  std::vector<int> bucket(nH), fill(bucketStart.begin(), bucketStart.end() - 1);
  for (int h = 0; h < nH; ++h) bucket[fill[std::min(tail[h], tip(h))]++] = h;

  EdgeGroups groups;
  groups.start.reserve(nH / 2 + 2);
  groups.members.reserve(nH);
  for (int v = 0; v < nVertices; ++v) {
    auto first = bucket.begin() + bucketStart[v], last = bucket.begin() + bucketStart[v + 1];
    // Buckets are tiny (a vertex's degree), so a sort by the other endpoint is cheap and keeps the output
    // deterministic.
    std::sort(first, last, [&](int a, int b) {
      const int oa = std::max(tail[a], tip(a)), ob = std::max(tail[b], tip(b));
      return oa != ob ? oa < ob : a < b;
    });
    for (auto it = first; it != last;) {
      const int other = std::max(tail[*it], tip(*it));
      groups.start.push_back(static_cast<int>(groups.members.size()));
      while (it != last && std::max(tail[*it], tip(*it)) == other) groups.members.push_back(*it++);
    }
  }
  groups.start.push_back(static_cast<int>(groups.members.size()));
  return groups;
}

EdgeGroups groupByIds(const std::vector<std::array<int, 3>>& cornerEdgeIds, const std::string& source) {
  const int nH = static_cast<int>(cornerEdgeIds.size()) * 3;
  int maxId = -1;
  for (int f = 0; f < static_cast<int>(cornerEdgeIds.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      if (cornerEdgeIds[f][k] < 0)
        throw InputError(describeAt(source, "face " + std::to_string(f) + ": edge index " +
                                                std::to_string(cornerEdgeIds[f][k]) + " is negative"));
      maxId = std::max(maxId, cornerEdgeIds[f][k]);
    }
  std::vector<int> count(maxId + 2, 0);
  for (const auto& ids : cornerEdgeIds)
    for (int id : ids) ++count[id + 1];
  for (int id = 0; id <= maxId; ++id)
    if (count[id + 1] == 0)
      throw InputError(describeAt(source, "edge " + std::to_string(id) + " is used by no face corner"));
  std::partial_sum(count.begin(), count.end(), count.begin());
  EdgeGroups groups;
  groups.start = count;
  groups.members.resize(nH);
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int h = 0; h < nH; ++h) groups.members[fill[cornerEdgeIds[h / 3][h % 3]]++] = h;
  return groups;
}

// The input checks that need no connectivity: sizes, index ranges and (for a soup) repeated vertices.
void checkFaceList(const std::vector<std::array<int, 3>>& inputFaces, int nVertices, const std::string& source,
                   const std::vector<std::array<int, 3>>& cornerEdgeIds) {
  if (inputFaces.empty()) throw InputError(describeAt(source, "the mesh has no faces"));
  if (nVertices <= 0) throw InputError(describeAt(source, "the mesh has no vertices"));
  if (!cornerEdgeIds.empty() && cornerEdgeIds.size() != inputFaces.size())
    throw InputError(describeAt(source, "edge indices given for " + std::to_string(cornerEdgeIds.size()) +
                                            " faces, expected one triple per face (" +
                                            std::to_string(inputFaces.size()) + ")"));
  const int nF = static_cast<int>(inputFaces.size());
  for (int f = 0; f < nF; ++f) {
    const auto& fv = inputFaces[f];
    for (int k = 0; k < 3; ++k)
      if (fv[k] < 0 || fv[k] >= nVertices)
        throw InputError(describeAt(source, "face " + std::to_string(f) + " " + faceString(fv) + ": vertex index " +
                                                std::to_string(fv[k]) + " out of range [0, " +
                                                std::to_string(nVertices) + ")"));
    // With explicit edge ids a Δ-complex face may repeat a vertex (a self-loop edge); a soup face may not.
    if (cornerEdgeIds.empty() && (fv[0] == fv[1] || fv[1] == fv[2] || fv[0] == fv[2]))
      throw InputError(describeAt(source, "face " + std::to_string(f) + " " + faceString(fv) + " repeats a vertex"));
  }
}

// Throws for an edge group of more than two halfedges (a non-manifold edge), naming its faces.
void checkManifoldEdges(const EdgeGroups& groups, const std::vector<int>& tail, const std::string& source) {
  const int nGroups = static_cast<int>(groups.start.size()) - 1;
  for (int g = 0; g < nGroups; ++g) {
    const int size = groups.start[g + 1] - groups.start[g];
    if (size > 2) {
      const int h0 = groups.members[groups.start[g]];
      std::string fs;
      for (int i = groups.start[g]; i < groups.start[g + 1]; ++i)
        fs += (fs.empty() ? "" : ", ") + std::to_string(groups.members[i] / 3);
      throw InputError(describeAt(source, "non-manifold edge (" + std::to_string(tail[h0]) + ", " +
                                              std::to_string(tail[HalfedgeMesh::next(h0)]) + ") is shared by " +
                                              std::to_string(size) + " faces: " + fs + "; at most 2 are allowed"));
    }
  }
}

// Which faces to flip so that glued halfedges run opposite ways: breadth-first over each component, keeping the
// orientation of its majority (so a mostly consistent input changes least). Throws for a non-orientable component and,
// with edge ids, for two faces glued with clashing orientations.
class OrientationSearch {
 public:
  OrientationSearch(const EdgeGroups& groups, const std::vector<int>& tail,
                    const std::vector<std::array<int, 3>>& edgeIds, const std::string& source)
      : tail_(tail), edgeIds_(edgeIds), source_(source), nF_(static_cast<int>(tail.size()) / 3) {
    findPartners(groups);
  }

  std::vector<signed char> run() {
    flipFace_.assign(nF_, -1);
    queue_.reserve(nF_);
    for (int seed = 0; seed < nF_; ++seed) {
      if (flipFace_[seed] >= 0) continue;
      orientComponent(seed);
      keepMajority();
    }
    return flipFace_;
  }

 private:
  void findPartners(const EdgeGroups& groups) {
    const int nGroups = static_cast<int>(groups.start.size()) - 1;
    partner_.assign(tail_.size(), kInvalid);
    for (int g = 0; g < nGroups; ++g)
      if (groups.start[g + 1] - groups.start[g] == 2) {
        const int a = groups.members[groups.start[g]], b = groups.members[groups.start[g] + 1];
        if (a / 3 == b / 3 && edgeIds_.empty())
          throw InputError(describeAt(source_, "face " + std::to_string(a / 3) + " is glued to itself"));
        partner_[a] = b;
        partner_[b] = a;
      }
  }

  void orientComponent(int seed) {
    flipFace_[seed] = 0;
    queue_.assign(1, seed);
    for (size_t qi = 0; qi < queue_.size(); ++qi) {
      const int f = queue_[qi];
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * f + k, p = partner_[h];
        if (p == kInvalid) continue;
        const int g = p / 3;
        const signed char want = static_cast<signed char>(flipFace_[f] ^ (disagree(f, k, h, p) ? 1 : 0));
        if (flipFace_[g] < 0) {
          flipFace_[g] = want;
          queue_.push_back(g);
        } else if (flipFace_[g] != want) {
          throw InputError(describeAt(source_,
                                      "the surface is not orientable: no consistent orientation exists for "
                                      "the component containing face " +
                                          std::to_string(seed) + " (conflict at faces " + std::to_string(f) + " and " +
                                          std::to_string(g) + ")"));
        }
      }
    }
  }

  // Same direction (tail(h) == tail(p)) means the two faces disagree in the input. A self-loop's direction cannot be
  // read off its vertices: Δ-complexes given with edge ids are taken as oriented by their corner order.
  bool disagree(int f, int k, int h, int p) const {
    using M = HalfedgeMesh;
    const bool sameWay = tail_[h] == tail_[p] && tail_[M::next(h)] == tail_[M::next(p)];
    const bool loop = tail_[h] == tail_[M::next(h)];
    if (!edgeIds_.empty() && sameWay && !loop)
      throw InputError(describeAt(source_, "faces " + std::to_string(f) + " and " + std::to_string(p / 3) +
                                               " are glued by edge_index " + std::to_string(edgeIds_[f][k]) +
                                               " with clashing orientations"));
    return sameWay && !loop;
  }

  void keepMajority() {
    size_t flipped = 0;
    for (int f : queue_) flipped += flipFace_[f];
    if (2 * flipped > queue_.size())
      for (int f : queue_) flipFace_[f] ^= 1;
  }

  const std::vector<int>& tail_;
  const std::vector<std::array<int, 3>>& edgeIds_;
  const std::string& source_;
  const int nF_;
  std::vector<int> partner_, queue_;
  std::vector<signed char> flipFace_;
};

// Every vertex must be used, and its corners must form exactly one fan.
void checkVertexFans(const HalfedgeMesh& m, const std::string& source) {
  const int nVertices = m.nVertices(), nH = m.nHalfedges();
  std::vector<int> corners(nVertices, 0);
  for (int h = 0; h < nH; ++h) ++corners[m.tail(h)];
  for (int v = 0; v < nVertices; ++v) {
    if (m.vertexHalfedge(v) == kInvalid)
      throw InputError(describeAt(
          source, "vertex " + std::to_string(v) + " belongs to no face (remove unreferenced vertices first)"));
    int count = 0;
    const int start = m.vertexHalfedge(v);
    int h = start;
    do {
      ++count;
      h = m.nextOutgoing(h);
    } while (h != kInvalid && h != start && count <= corners[v]);
    if (count != corners[v])
      throw InputError(describeAt(source, "pinched vertex " + std::to_string(v) + ": its " +
                                              std::to_string(corners[v]) +
                                              " faces form more than one fan (one fan "
                                              "has " +
                                              std::to_string(count) + ")"));
  }
}

}  // namespace

// === construction

HalfedgeMesh HalfedgeMesh::fromFaces(const std::vector<std::array<int, 3>>& inputFaces, int nVertices,
                                     const std::string& source, BuildReport* report,
                                     const std::vector<std::array<int, 3>>& cornerEdgeIds) {
  checkFaceList(inputFaces, nVertices, source, cornerEdgeIds);
  const int nF = static_cast<int>(inputFaces.size());
  std::vector<std::array<int, 3>> faces = inputFaces;
  std::vector<std::array<int, 3>> edgeIds = cornerEdgeIds;
  HalfedgeMesh m;
  const int nH = 3 * nF;
  m.tail_.resize(nH);
  auto loadTails = [&] {
    for (int f = 0; f < nF; ++f)
      for (int k = 0; k < 3; ++k) m.tail_[3 * f + k] = faces[f][k];
  };
  loadTails();

  EdgeGroups groups = edgeIds.empty() ? groupByEndpoints(m.tail_, nVertices) : groupByIds(edgeIds, source);
  checkManifoldEdges(groups, m.tail_, source);

  // --- orientation: two glued halfedges running the same way force opposite orientations.
  const std::vector<signed char> flipFace = OrientationSearch(groups, m.tail_, edgeIds, source).run();
  int reoriented = 0;
  for (int f = 0; f < nF; ++f)
    if (flipFace[f]) {
      ++reoriented;
      std::swap(faces[f][1], faces[f][2]);
      // Corner k's edge runs k -> k+1: swapping vertices 1 and 2 reverses the cycle, so edges (0,1),(1,2),(2,0)
      // become (0,2),(2,1),(1,0): corner 0 now carries old edge 2, corner 1 old edge 1, corner 2 old edge 0.
      if (!edgeIds.empty()) std::swap(edgeIds[f][0], edgeIds[f][2]);
    }
  if (report) report->reorientedFaces = reoriented;
  if (reoriented > 0) {
    loadTails();
    groups = edgeIds.empty() ? groupByEndpoints(m.tail_, nVertices) : groupByIds(edgeIds, source);
  }

  // --- edges and twins
  m.twin_.assign(nH, kInvalid);
  m.edge_.assign(nH, kInvalid);
  m.edgeHalfedge_.resize(groups.start.size() - 1);
  for (int g = 0; g + 1 < static_cast<int>(groups.start.size()); ++g) {
    const int a = groups.members[groups.start[g]];
    m.edge_[a] = g;
    m.edgeHalfedge_[g] = a;
    if (groups.start[g + 1] - groups.start[g] == 2) {
      const int b = groups.members[groups.start[g] + 1];
      if (m.tail_[a] == m.tail_[b] && m.tail_[next(a)] == m.tail_[next(b)] && m.tail_[a] != m.tail_[next(a)])
        throw std::logic_error("HalfedgeMesh: orientation pass left two glued halfedges running the same way");
      m.twin_[a] = b;
      m.twin_[b] = a;
      m.edge_[b] = g;
    }
  }

  // --- vertices: an outgoing halfedge each (the boundary one where there is one), then one fan per vertex.
  m.vertexHalfedge_.assign(nVertices, kInvalid);
  for (int h = 0; h < nH; ++h) {
    const int v = m.tail_[h];
    if (m.vertexHalfedge_[v] == kInvalid || m.twin_[h] == kInvalid) m.vertexHalfedge_[v] = h;
  }
  checkVertexFans(m, source);
  return m;
}

// === navigation and topology

int HalfedgeMesh::vertexDegree(int v) const {
  int count = 0;
  const int start = vertexHalfedge_[v];
  int h = start;
  do {
    ++count;
    h = nextOutgoing(h);
  } while (h != kInvalid && h != start);
  return count;
}

int HalfedgeMesh::nextBoundaryHalfedge(int h) const {
  int n = next(h);
  while (twin_[n] != kInvalid) n = next(twin_[n]);
  return n;
}

std::vector<std::vector<int>> HalfedgeMesh::boundaryLoops() const {
  std::vector<std::vector<int>> loops;
  std::vector<char> seen(nHalfedges(), 0);
  for (int h = 0; h < nHalfedges(); ++h) {
    if (twin_[h] != kInvalid || seen[h]) continue;
    loops.emplace_back();
    int b = h;
    do {
      seen[b] = 1;
      loops.back().push_back(b);
      b = nextBoundaryHalfedge(b);
    } while (b != h);
  }
  return loops;
}

std::vector<int> HalfedgeMesh::faceComponents() const {
  std::vector<int> comp(nFaces(), kInvalid);
  std::vector<int> queue;
  int count = 0;
  for (int seed = 0; seed < nFaces(); ++seed) {
    if (comp[seed] != kInvalid) continue;
    comp[seed] = count;
    queue.assign(1, seed);
    for (size_t qi = 0; qi < queue.size(); ++qi)
      for (int k = 0; k < 3; ++k) {
        const int t = twin_[3 * queue[qi] + k];
        if (t != kInvalid && comp[t / 3] == kInvalid) {
          comp[t / 3] = count;
          queue.push_back(t / 3);
        }
      }
    ++count;
  }
  return comp;
}

std::vector<ComponentTopology> HalfedgeMesh::components() const {
  const std::vector<int> comp = faceComponents();
  const int count = comp.empty() ? 0 : *std::max_element(comp.begin(), comp.end()) + 1;
  std::vector<ComponentTopology> result(count);
  for (int f = 0; f < nFaces(); ++f) ++result[comp[f]].faces;
  for (int v = 0; v < nVertices(); ++v) ++result[comp[vertexHalfedge_[v] / 3]].vertices;
  for (int e = 0; e < nEdges(); ++e) ++result[comp[edgeHalfedge_[e] / 3]].edges;
  for (const auto& loop : boundaryLoops()) ++result[comp[loop.front() / 3]].boundaryLoops;
  for (auto& c : result) {
    c.eulerCharacteristic = c.vertices - c.edges + c.faces;
    c.genus = (2 - c.eulerCharacteristic - c.boundaryLoops) / 2;
  }
  return result;
}

// === mutation

bool HalfedgeMesh::flip(int e) {
  const int ha = edgeHalfedge_[e], hb = twin_[ha];
  if (hb == kInvalid) return false;
  const int fa = face(ha), fb = face(hb);
  if (fa == fb) return false;
  // Before: fa = (a->b = ha, b->c = na, c->a = pa), fb = (b->a = hb, a->d = nb, d->b = pb).
  const int na = next(ha), pa = prev(ha), nb = next(hb), pb = prev(hb);
  const int a = tail_[ha], b = tail_[hb], c = tail_[pa], d = tail_[pb];
  // After: fa = (d->c, c->a, a->d), fb = (c->d, d->b, b->c). New slots:
  const int h0 = 3 * fa, h1 = 3 * fa + 1, h2 = 3 * fa + 2, g0 = 3 * fb, g1 = 3 * fb + 1, g2 = 3 * fb + 2;
  const int oldSlots[6] = {ha, na, pa, hb, nb, pb};
  // Where each old halfedge's role goes: pa->h1, nb->h2, pb->g1, na->g2; the flipped pair ha/hb have no successor,
  // but a vertex whose representative was one of them gets a->d (h2) or b->c (g2).
  const int newSlot[6] = {h2, g2, h1, g2, h2, g1};
  auto remap = [&](int h) {
    for (int i = 0; i < 6; ++i)
      if (oldSlots[i] == h) return newSlot[i];
    return h;
  };
  struct Old {
    int twin, edge;
  };
  const Old oNa{twin_[na], edge_[na]}, oPa{twin_[pa], edge_[pa]}, oNb{twin_[nb], edge_[nb]}, oPb{twin_[pb], edge_[pb]};
  int vh[4] = {vertexHalfedge_[a], vertexHalfedge_[b], vertexHalfedge_[c], vertexHalfedge_[d]};
  for (int& h : vh) h = remap(h);

  auto place = [&](int slot, int tailV, const Old& o) {
    tail_[slot] = tailV;
    edge_[slot] = o.edge;
    edgeHalfedge_[o.edge] = slot;
  };
  place(h1, c, oPa);
  place(h2, a, oNb);
  place(g1, d, oPb);
  place(g2, b, oNa);
  // Twins after every slot holds its new role, so that outer halfedges glued to each other (degenerate Δ-complex
  // configurations) are remapped too.
  auto glue = [&](int slot, int oldTwin) {
    const int t = oldTwin == kInvalid ? kInvalid : remap(oldTwin);
    twin_[slot] = t;
    if (t != kInvalid) twin_[t] = slot;
  };
  glue(h1, oPa.twin);
  glue(h2, oNb.twin);
  glue(g1, oPb.twin);
  glue(g2, oNa.twin);
  tail_[h0] = d;
  tail_[g0] = c;
  edge_[h0] = edge_[g0] = e;
  twin_[h0] = g0;
  twin_[g0] = h0;
  edgeHalfedge_[e] = h0;
  vertexHalfedge_[a] = vh[0];
  vertexHalfedge_[b] = vh[1];
  vertexHalfedge_[c] = vh[2];
  vertexHalfedge_[d] = vh[3];
  return true;
}

int HalfedgeMesh::splitFace(int f) {
  // Face f = (a, b, c) with halfedges ab, bc, ca becomes three faces around the new vertex p:
  // f = (a, b, p), f1 = (b, c, p), f2 = (c, a, p). Outer halfedges keep their edges; three new edges pa, pb, pc.
  const int v = nVertices();
  const int hab = 3 * f, hbc = 3 * f + 1, hca = 3 * f + 2;
  const int a = tail_[hab], b = tail_[hbc], c = tail_[hca];
  const int f1 = nFaces(), f2 = f1 + 1;
  // The roles of bc and ca move to the new faces; a twin inside face f itself (a Δ-complex face glued to itself) must
  // follow them.
  auto moved = [&](int h) { return h == hbc ? 3 * f1 : (h == hca ? 3 * f2 : h); };
  const int tBc = twin_[hbc] == kInvalid ? kInvalid : moved(twin_[hbc]);
  const int tCa = twin_[hca] == kInvalid ? kInvalid : moved(twin_[hca]);
  const int eBc = edge_[hbc], eCa = edge_[hca];
  tail_.resize(tail_.size() + 6);
  twin_.resize(twin_.size() + 6);
  edge_.resize(edge_.size() + 6);
  const int eA = nEdges(), eB = eA + 1, eC = eA + 2;
  edgeHalfedge_.resize(edgeHalfedge_.size() + 3);
  vertexHalfedge_.push_back(kInvalid);

  auto set = [&](int h, int t, int tw, int ed) {
    tail_[h] = t;
    twin_[h] = tw;
    edge_[h] = ed;
    if (tw != kInvalid) twin_[tw] = h;
  };
  // f: a->b (unchanged), b->p, p->a
  set(3 * f + 1, b, kInvalid, eB);
  set(3 * f + 2, v, kInvalid, eA);
  // f1: b->c (old bc), c->p, p->b
  set(3 * f1 + 0, b, tBc, eBc);
  set(3 * f1 + 1, c, kInvalid, eC);
  set(3 * f1 + 2, v, 3 * f + 1, eB);
  // f2: c->a (old ca), a->p, p->c
  set(3 * f2 + 0, c, tCa, eCa);
  set(3 * f2 + 1, a, 3 * f + 2, eA);
  set(3 * f2 + 2, v, 3 * f1 + 1, eC);
  edgeHalfedge_[eBc] = 3 * f1;
  edgeHalfedge_[eCa] = 3 * f2;
  edgeHalfedge_[eA] = 3 * f + 2;
  edgeHalfedge_[eB] = 3 * f + 1;
  edgeHalfedge_[eC] = 3 * f1 + 1;
  vertexHalfedge_[v] = 3 * f + 2;
  // Representatives that pointed at moved halfedges: bc moved to f1 slot 0, ca to f2 slot 0.
  auto fix = [&](int vert, int oldH, int newH) {
    if (vertexHalfedge_[vert] == oldH) vertexHalfedge_[vert] = newH;
  };
  fix(b, hbc, 3 * f1);
  fix(c, hca, 3 * f2);
  return v;
}

int HalfedgeMesh::splitEdge(int e) {
  // Edge e = (a -> b) seen from ha = edgeHalfedge(e) in face (a, b, c), and from hb = twin (b -> a) in (b, a, d) if
  // interior. New vertex p on e. Face (a,b,c) becomes (a,p,c) [in place] + (p,b,c) [new]; (b,a,d) becomes (b,p,d)
  // [in place] + (p,a,d) [new]. Edge e keeps a-p; new edge p-b, and new interior edges p-c, p-d.
  const int ha = edgeHalfedge_[e], hb = twin_[ha];
  if (hb != kInvalid && face(ha) == face(hb)) return kInvalid;  // a face folded onto itself along e
  const int v = nVertices();
  const int na = next(ha), pa = prev(ha);
  const int a = tail_[ha], b = tail_[na], c = tail_[pa];
  const int ePb = nEdges(), ePc = ePb + 1;
  const int fNew1 = nFaces(), fNew2 = fNew1 + 1;
  // The roles of na (b -> c) and, for an interior edge, nb (a -> d) move to the new faces; twins that point at them
  // (possible in a Δ-complex) follow.
  const int nbOld = hb == kInvalid ? kInvalid : next(hb);
  auto moved = [&](int h) { return h == na ? 3 * fNew1 + 1 : (h != kInvalid && h == nbOld ? 3 * fNew2 + 1 : h); };
  const int eNa = edge_[na], tNa = moved(twin_[na]);
  vertexHalfedge_.push_back(kInvalid);
  tail_.resize(tail_.size() + 3);
  twin_.resize(twin_.size() + 3);
  edge_.resize(edge_.size() + 3);
  edgeHalfedge_.resize(edgeHalfedge_.size() + 2);
  auto set = [&](int h, int t, int tw, int ed) {
    tail_[h] = t;
    twin_[h] = tw;
    edge_[h] = ed;
    if (tw != kInvalid) twin_[tw] = h;
  };
  // In place: (a -> p = ha, p -> c = na, c -> a = pa).
  set(na, v, kInvalid, ePc);
  // New face fNew1: (p -> b, b -> c, c -> p).
  const int q0 = 3 * fNew1, q1 = q0 + 1, q2 = q0 + 2;
  set(q0, v, kInvalid, ePb);
  set(q1, b, tNa, eNa);
  set(q2, c, na, ePc);
  edgeHalfedge_[eNa] = q1;
  edgeHalfedge_[ePc] = na;
  edgeHalfedge_[ePb] = q0;
  if (vertexHalfedge_[b] == na) vertexHalfedge_[b] = q1;
  vertexHalfedge_[v] = q0;  // boundary representative if e is a boundary edge (q0 has no twin then)

  if (hb != kInvalid) {
    // (b -> a = hb, a -> d = nb, d -> b = pb) becomes (b -> p = hb, p -> d, d -> b = pb) + new (p -> a, a -> d, d ->
    // p).
    const int nb = next(hb), pb = prev(hb);
    const int d = tail_[pb];
    const int eNb = edge_[nb], tNb = moved(twin_[nb]);
    const int ePd = nEdges();
    edgeHalfedge_.push_back(kInvalid);
    tail_.resize(tail_.size() + 3);
    twin_.resize(twin_.size() + 3);
    edge_.resize(edge_.size() + 3);
    const int r0 = 3 * fNew2, r1 = r0 + 1, r2 = r0 + 2;
    // hb now runs b -> p and is glued to q0 (p -> b) on the new edge ePb; ha (a -> p) is glued to r0 (p -> a) on e.
    set(hb, b, q0, ePb);
    set(nb, v, kInvalid, ePd);
    set(r0, v, ha, e);
    set(r1, a, tNb, eNb);
    set(r2, d, nb, ePd);
    edgeHalfedge_[eNb] = r1;
    edgeHalfedge_[ePd] = nb;
    if (vertexHalfedge_[a] == nb) vertexHalfedge_[a] = r1;
    vertexHalfedge_[v] = q0;
  }
  edgeHalfedge_[e] = ha;
  return v;
}

namespace {

// Records that the element now at `from` moves to `to`; an element moved before (its entry ends at `from`) keeps one
// entry from its original index, so that applyMoves reads every value from the data as it was before the removal.
void recordMove(std::vector<std::pair<int, int>>& moves, int from, int to) {
  if (from == to) return;
  for (auto& m : moves)
    if (m.second == from) {
      m.second = to;
      return;
    }
  moves.push_back({from, to});
}

}  // namespace

bool HalfedgeMesh::removeDegree3Vertex(int v, ElementMoves& moves, int& mergedFace) {
  moves = {};
  if (v < 0 || v >= nVertices() || isBoundaryVertex(v)) return false;
  // Outgoing halfedges h_i = v -> u_i, counter-clockwise; face f_i = (v, u_i, u_{i+1}) has outer halfedge
  // o_i = next(h_i) = u_i -> u_{i+1} and prev(h_i) = u_{i+1} -> v.
  int h[3];
  h[0] = vertexHalfedge_[v];
  for (int i = 1; i < 3; ++i) h[i] = nextOutgoing(h[i - 1]);
  if (nextOutgoing(h[2]) != h[0]) return false;
  for (int i = 0; i < 3; ++i)
    if (tip(h[i]) == v) return false;
  int o[3], u[3], spoke[3];
  for (int i = 0; i < 3; ++i) {
    o[i] = next(h[i]);
    u[i] = tail_[o[i]];
    spoke[i] = edge_[h[i]];
  }
  const int F = face(h[0]);
  // The merged face takes f_0's slot, corner i holding o_i. Old halfedges that survive in it (the o_i), and those whose
  // role it takes over as a vertex's representative (u_{i+1} -> v becomes u_{i+1} -> u_{i+2}), map to its slots; a twin
  // inside the star itself (a Δ-complex folded onto the star) follows.
  auto remap = [&](int x) {
    for (int i = 0; i < 3; ++i) {
      if (x == o[i]) return 3 * F + i;
      if (x == prev(h[i])) return 3 * F + (i + 1) % 3;
    }
    return x;
  };
  int newTwin[3], newEdgeRep[3], newVertexRep[3];
  for (int i = 0; i < 3; ++i) {
    newTwin[i] = twin_[o[i]] == kInvalid ? kInvalid : remap(twin_[o[i]]);
    newEdgeRep[i] = remap(edgeHalfedge_[edge_[o[i]]]);
    newVertexRep[i] = remap(vertexHalfedge_[u[i]]);
  }
  int edgeOf[3];
  for (int i = 0; i < 3; ++i) edgeOf[i] = edge_[o[i]];
  for (int i = 0; i < 3; ++i) recordMove(moves.halfedges, o[i], 3 * F + i);
  for (int i = 0; i < 3; ++i) {
    tail_[3 * F + i] = u[i];
    edge_[3 * F + i] = edgeOf[i];
  }
  for (int i = 0; i < 3; ++i) {
    twin_[3 * F + i] = newTwin[i];
    if (newTwin[i] != kInvalid) twin_[newTwin[i]] = 3 * F + i;
    edgeHalfedge_[edgeOf[i]] = newEdgeRep[i];
    vertexHalfedge_[u[i]] = newVertexRep[i];
  }
  mergedFace = F;

  // Compaction by swap-with-last, holes in decreasing order: the last element is then never a hole itself (larger holes
  // are gone), and each move keeps twins, edge and vertex representatives pointing at the element's new slots.
  int faceHoles[2] = {face(h[1]), face(h[2])};
  std::sort(faceHoles, faceHoles + 2, std::greater<int>());
  for (int hole : faceHoles) {
    const int L = nFaces() - 1;
    if (hole != L) {
      for (int k = 0; k < 3; ++k) {
        const int from = 3 * L + k, to = 3 * hole + k;
        tail_[to] = tail_[from];
        edge_[to] = edge_[from];
        int tw = twin_[from];
        if (tw != kInvalid && face(tw) == L) tw = 3 * hole + tw % 3;
        twin_[to] = tw;
        if (tw != kInvalid) twin_[tw] = to;
        if (edgeHalfedge_[edge_[to]] == from) edgeHalfedge_[edge_[to]] = to;
        if (vertexHalfedge_[tail_[to]] == from) vertexHalfedge_[tail_[to]] = to;
        recordMove(moves.halfedges, from, to);
      }
      if (L == mergedFace)
        mergedFace = hole;
      else
        recordMove(moves.faces, L, hole);
    }
    tail_.resize(tail_.size() - 3);
    twin_.resize(twin_.size() - 3);
    edge_.resize(edge_.size() - 3);
  }
  std::sort(spoke, spoke + 3, std::greater<int>());
  for (int hole : spoke) {
    const int L = nEdges() - 1;
    if (hole != L) {
      const int a = edgeHalfedge_[L];
      edgeHalfedge_[hole] = a;
      edge_[a] = hole;
      if (twin_[a] != kInvalid) edge_[twin_[a]] = hole;
      recordMove(moves.edges, L, hole);
    }
    edgeHalfedge_.pop_back();
  }
  const int L = nVertices() - 1;
  if (v != L) {
    const int start = vertexHalfedge_[L];
    int x = start;
    do {
      tail_[x] = v;
      x = nextOutgoing(x);
    } while (x != kInvalid && x != start);
    vertexHalfedge_[v] = start;
    recordMove(moves.vertices, L, v);
  }
  vertexHalfedge_.pop_back();
  return true;
}

// === checks

void HalfedgeMesh::checkInvariants() const {
  auto fail = [](const std::string& what) { throw std::logic_error("HalfedgeMesh invariant violated: " + what); };
  const int nH = nHalfedges();
  if (twin_.size() != tail_.size() || edge_.size() != tail_.size()) fail("array sizes differ");
  for (int h = 0; h < nH; ++h) {
    const int t = twin_[h];
    if (t != kInvalid) {
      if (t < 0 || t >= nH || twin_[t] != h) fail("twin not symmetric at halfedge " + std::to_string(h));
      if (tail_[t] != tip(h) || tip(t) != tail_[h]) fail("twins do not reverse at halfedge " + std::to_string(h));
      if (edge_[t] != edge_[h]) fail("twins on different edges at halfedge " + std::to_string(h));
    }
    if (edge_[h] < 0 || edge_[h] >= nEdges()) fail("edge index out of range at halfedge " + std::to_string(h));
  }
  for (int e = 0; e < nEdges(); ++e)
    if (edge_[edgeHalfedge_[e]] != e) fail("edgeHalfedge inconsistent at edge " + std::to_string(e));
  std::vector<int> corners(nVertices(), 0);
  std::vector<char> hasBoundaryOut(nVertices(), 0);
  for (int h = 0; h < nH; ++h) {
    ++corners[tail_[h]];
    if (twin_[h] == kInvalid) hasBoundaryOut[tail_[h]] = 1;
  }
  for (int v = 0; v < nVertices(); ++v) {
    const int h0 = vertexHalfedge_[v];
    if (h0 < 0 || h0 >= nH || tail_[h0] != v) fail("vertexHalfedge not outgoing at vertex " + std::to_string(v));
    if (hasBoundaryOut[v] && twin_[h0] != kInvalid)
      fail("boundary vertex " + std::to_string(v) + " rep not on boundary");
    if (vertexDegree(v) != corners[v]) fail("fan of vertex " + std::to_string(v) + " is not closed");
  }
}

}  // namespace conformesh::intrinsic
