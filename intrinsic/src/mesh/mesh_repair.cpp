// mesh_repair.cpp — the steps of repairMesh (see mesh_repair.h) as methods of MeshRepairer over one shared state: the
// faces, the vertices' origins in the input (for positions, properties and edge lengths) and the report.
#include "conformesh/intrinsic/mesh/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/halfedge_mesh.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::intrinsic {

namespace {

std::uint64_t repairPairKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

std::string faceText(int f, const std::array<int, 3>& v) {
  return "face " + std::to_string(f) + " (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
         std::to_string(v[2]) + ")";
}

// Union–find over corner ids 3f + k.
struct Fans {
  std::vector<int> parent;
  explicit Fans(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

class MeshRepairer {
 public:
  MeshRepairer(const MeshData& in, const RepairOptions& o) : in_(in), o_(o) {
    faces_ = in.faces;
    faceOrigin_.resize(faces_.size());
    std::iota(faceOrigin_.begin(), faceOrigin_.end(), 0);
    origin_.resize(in.nVertices);
    std::iota(origin_.begin(), origin_.end(), 0);
  }

  MeshData run(RepairReport* reportOut) {
    if (o_.mergeTolerance >= 0 && !in_.positions.empty()) mergeVertices();
    dropDegenerateFaces();
    dropDuplicateFaces();
    for (int round = 0; round < 3 && cutNonManifoldEdges(round); ++round) splitFans();
    splitFans();
    MeshData out = compactAndOrient();
    if (reportOut) *reportOut = report_;
    return out;
  }

 private:
  void note(RepairReport::Step& s, const std::string& what) {
    if (static_cast<int>(s.examples.size()) < o_.examples) s.examples.push_back(what);
    ++s.count;
  }

  // Grid hashing with cells of the merge distance: every pair closer than it lies in neighbouring cells. Boundary
  // vertices are taken in index order and each joins the lowest earlier representative within the distance.
  void mergeVertices() {
    Eigen::Vector3d lo = in_.positions[0], hi = lo;
    for (const auto& p : in_.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double d = o_.mergeTolerance * (hi - lo).norm();
    report_.mergeDistance = d;
    if (!std::isfinite(d)) return;  // toTriangulation names the non-finite coordinate
    const double cell = d > 0 ? d : 1.0;
    auto cellOf = [&](const Eigen::Vector3d& p, int axis) {
      return static_cast<long long>(std::floor((p[axis] - lo[axis]) / cell));
    };
    auto key = [](long long x, long long y, long long z) {
      return static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL ^
             static_cast<std::uint64_t>(z) * 83492791ULL;
    };
    std::unordered_multimap<std::uint64_t, int> grid;
    std::vector<int> rep(in_.nVertices);
    const std::vector<char> onBoundary = boundaryVertices();
    for (int v = 0; v < in_.nVertices; ++v) {
      rep[v] = v;
      if (!onBoundary[v]) continue;
      const Eigen::Vector3d& p = in_.positions[v];
      const long long cx = cellOf(p, 0), cy = cellOf(p, 1), cz = cellOf(p, 2);
      for (long long dx = -1; dx <= 1 && rep[v] == v; ++dx)
        for (long long dy = -1; dy <= 1 && rep[v] == v; ++dy)
          for (long long dz = -1; dz <= 1 && rep[v] == v; ++dz) {
            const auto range = grid.equal_range(key(cx + dx, cy + dy, cz + dz));
            for (auto it = range.first; it != range.second; ++it)
              if ((in_.positions[it->second] - p).norm() <= d) {
                rep[v] = std::min(rep[v], it->second);
              }
          }
      if (rep[v] == v) {
        grid.emplace(key(cx, cy, cz), v);
      } else {
        note(report_.mergedVertices, "vertex " + std::to_string(v) + " -> " + std::to_string(rep[v]));
      }
    }
    for (auto& f : faces_)
      for (int& v : f) v = rep[v];
  }

  // Vertices on an edge that only one face of the input uses: the only ones merged (stitching borders, as CGAL's
  // stitch_borders does). Coincident vertices inside a surface are left apart: merging them would pinch it.
  std::vector<char> boundaryVertices() const {
    std::unordered_map<std::uint64_t, int> uses;
    uses.reserve(2 * faces_.size());
    for (const auto& f : faces_)
      for (int k = 0; k < 3; ++k) ++uses[repairPairKey(f[k], f[(k + 1) % 3])];
    std::vector<char> on(in_.nVertices, 0);
    for (const auto& f : faces_)
      for (int k = 0; k < 3; ++k)
        if (uses[repairPairKey(f[k], f[(k + 1) % 3])] == 1) on[f[k]] = on[f[(k + 1) % 3]] = 1;
    return on;
  }

  bool degenerate(const std::array<int, 3>& v) const {
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return true;
    double l[3];
    if (!in_.positions.empty()) {
      for (int k = 0; k < 3; ++k) l[k] = (in_.positions[origin_[v[k]]] - in_.positions[origin_[v[(k + 1) % 3]]]).norm();
      const Eigen::Vector3d n = (in_.positions[origin_[v[1]]] - in_.positions[origin_[v[0]]])
                                    .cross(in_.positions[origin_[v[2]]] - in_.positions[origin_[v[0]]]);
      const double longest = std::max({l[0], l[1], l[2]});
      if (0.5 * n.norm() <= o_.degenerateTolerance * longest * longest) return true;
    } else {
      for (int k = 0; k < 3; ++k) {
        const auto it = lengthOf_.find(repairPairKey(origin_[v[k]], origin_[v[(k + 1) % 3]]));
        if (it == lengthOf_.end()) return false;  // toTriangulation names the missing length
        l[k] = it->second;
      }
    }
    return !isValidTriangle(in_.background, l[0], l[1], l[2]);
  }

  void dropDegenerateFaces() {
    for (size_t i = 0; i < in_.edges.size(); ++i)
      lengthOf_.emplace(repairPairKey(in_.edges[i].v0, in_.edges[i].v1), in_.edges[i].length);
    keepFaces([&](size_t f) {
      if (!degenerate(faces_[f])) return true;
      note(report_.degenerateFaces, faceText(faceOrigin_[f], in_.faces[faceOrigin_[f]]));
      return false;
    });
  }

  void dropDuplicateFaces() {
    struct TripleHash {
      size_t operator()(const std::array<int, 3>& t) const {
        return std::hash<std::uint64_t>()(repairPairKey(t[0], t[1]) * 1000003ULL ^ static_cast<std::uint64_t>(t[2]));
      }
    };
    std::unordered_map<std::array<int, 3>, int, TripleHash> seen;
    seen.reserve(2 * faces_.size());
    std::unordered_map<std::uint64_t, int> uses;
    for (const auto& f : faces_)
      for (int k = 0; k < 3; ++k) ++uses[repairPairKey(f[k], f[(k + 1) % 3])];
    keepFaces([&](size_t f) {
      // A face and its copy alone on their edges close up (the doubled triangle, a valid surface): kept.
      bool crowded = false;
      for (int k = 0; k < 3; ++k) crowded = crowded || uses[repairPairKey(faces_[f][k], faces_[f][(k + 1) % 3])] > 2;
      if (!crowded) return true;
      std::array<int, 3> k = faces_[f];
      std::sort(k.begin(), k.end());
      const auto [it, isNew] = seen.emplace(k, faceOrigin_[f]);
      if (!isNew)
        note(report_.duplicateFaces, faceText(faceOrigin_[f], in_.faces[faceOrigin_[f]]) + " repeats face " +
                                         std::to_string(it->second));
      return isNew;
    });
  }

  template <class Keep>
  void keepFaces(Keep keep) {
    size_t w = 0;
    std::vector<int> moved(faces_.size(), -1);
    for (size_t f = 0; f < faces_.size(); ++f)
      if (keep(f)) faces_[w] = faces_[f], faceOrigin_[w] = faceOrigin_[f], moved[f] = static_cast<int>(w++);
    faces_.resize(w), faceOrigin_.resize(w);
    std::unordered_set<int> cut;
    for (int h : cut_)
      if (moved[h / 3] >= 0) cut.insert(3 * moved[h / 3] + h % 3);
    cut_.swap(cut);
  }

  // Halfedges 3f + k grouped by their vertex pair.
  std::unordered_map<std::uint64_t, std::vector<int>> edgeGroups() const {
    std::unordered_map<std::uint64_t, std::vector<int>> groups;
    groups.reserve(2 * faces_.size());
    for (size_t f = 0; f < faces_.size(); ++f)
      for (int k = 0; k < 3; ++k) groups[repairPairKey(faces_[f][k], faces_[f][(k + 1) % 3])].push_back(3 * f + k);
    return groups;
  }

  // Edges in more than two faces become boundary: round 0 keeps the first face and the first later one running the
  // other way (else the second) glued, round 1 (an edge still shared after the fans were split) keeps none glued,
  // round 2 drops the faces beyond the first two. Returns whether any edge was non-manifold.
  bool cutNonManifoldEdges(int round) {
    bool any = false;
    std::vector<char> drop(faces_.size(), 0);
    for (auto& [key, hs] : edgeGroups()) {
      if (hs.size() <= 2) continue;
      any = true;
      const int a = faces_[hs[0] / 3][hs[0] % 3];
      if (round == 0)
        note(report_.nonManifoldEdges, "edge (" + std::to_string(origin_[a]) + ", " +
                                           std::to_string(origin_[faces_[hs[0] / 3][(hs[0] % 3 + 1) % 3]]) + ") in " +
                                           std::to_string(hs.size()) + " faces");
      size_t partner = 1;
      for (size_t i = 1; i < hs.size(); ++i)
        if (faces_[hs[i] / 3][hs[i] % 3] != a) {
          partner = i;
          break;
        }
      for (size_t i = 0; i < hs.size(); ++i) {
        const bool kept = round == 0 ? (i == 0 || i == partner) : false;
        if (round == 2 && i >= 2) drop[hs[i] / 3] = 1;
        if (!kept) cut_.insert(hs[i]);
      }
    }
    if (round == 2) keepFaces([&](size_t f) { return !drop[f]; });
    return any && round < 2;
  }

  // Corners around a vertex are in one fan when joined across glued edges (two halfedges, neither cut); each fan
  // beyond the first gets its own copy of the vertex.
  void splitFans() {
    const int nC = static_cast<int>(3 * faces_.size());
    Fans fans(nC);
    for (auto& [key, hs] : edgeGroups()) {
      int glued[2], n = 0;
      for (int h : hs)
        if (!cut_.count(h) && n < 3) glued[std::min(n++, 1)] = h;
      if (n != 2) continue;
      const int h = glued[0], g = glued[1];
      const int hTail = h, hTip = 3 * (h / 3) + (h % 3 + 1) % 3;
      const int gTail = g, gTip = 3 * (g / 3) + (g % 3 + 1) % 3;
      const int a = faces_[h / 3][h % 3];
      if (faces_[g / 3][g % 3] == a) {
        fans.join(hTail, gTail), fans.join(hTip, gTip);
      } else {
        fans.join(hTail, gTip), fans.join(hTip, gTail);
      }
    }
    std::unordered_map<int, int> copyOfRoot;  // fan root -> vertex id
    std::vector<int> firstRoot(origin_.size(), -1);
    for (int c = 0; c < nC; ++c) {
      int& v = faces_[c / 3][c % 3];
      const int root = fans.find(c);
      if (firstRoot[v] < 0 || firstRoot[v] == root) {
        firstRoot[v] = root;
        continue;
      }
      auto it = copyOfRoot.find(root);
      if (it == copyOfRoot.end()) {
        note(report_.pinchedVertices, "vertex " + std::to_string(origin_[v]) + " (fan of face " +
                                          std::to_string(faceOrigin_[c / 3]) + ")");
        it = copyOfRoot.emplace(root, static_cast<int>(origin_.size())).first;
        origin_.push_back(origin_[v]);
        firstRoot.push_back(root);
      }
      v = it->second;
    }
  }

  MeshData compactAndOrient();
  MeshData carryAlong(const std::vector<int>& vertexOf) const;

  const MeshData& in_;
  const RepairOptions& o_;
  RepairReport report_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<int> faceOrigin_;  // input face of each face
  std::vector<int> origin_;      // input vertex of each vertex (copies share their original's)
  std::unordered_set<int> cut_;  // halfedges 3f + k no longer glued
  std::unordered_map<std::uint64_t, double> lengthOf_;
};

// Vertices used by no face are removed; the orientation is HalfedgeMesh's (a breadth-first search keeping each
// component's majority), read back from the built mesh.
MeshData MeshRepairer::compactAndOrient() {
  if (faces_.empty()) throw InputError(describeAt(in_.source, "repair removed every face (all were degenerate)"));
  std::vector<int> index(origin_.size(), -1), vertexOf;  // kept in the input's order, copies after
  for (const auto& f : faces_)
    for (int v : f) index[v] = 0;
  for (size_t v = 0; v < index.size(); ++v)
    if (index[v] == 0) index[v] = static_cast<int>(vertexOf.size()), vertexOf.push_back(static_cast<int>(v));
  for (auto& f : faces_)
    for (int& v : f) v = index[v];
  std::vector<char> usedInInput(in_.nVertices, 0);
  for (const auto& f : in_.faces)
    for (int v : f) usedInInput[v] = 1;
  for (int v = 0; v < in_.nVertices; ++v)
    if (!usedInInput[v]) note(report_.unreferencedVertices, "vertex " + std::to_string(v));
  BuildReport build;
  const HalfedgeMesh m = HalfedgeMesh::fromFaces(faces_, static_cast<int>(vertexOf.size()), in_.source, &build);
  for (size_t f = 0; f < faces_.size(); ++f) {
    const std::array<int, 3> oriented = {m.faceVertex(f, 0), m.faceVertex(f, 1), m.faceVertex(f, 2)};
    if (oriented != faces_[f]) note(report_.reorientedFaces, "face " + std::to_string(faceOrigin_[f]));
    faces_[f] = oriented;
  }
  return carryAlong(vertexOf);
}

// Positions, vertex properties and (for metric-only meshes) edge lengths of the result, from the input's.
MeshData MeshRepairer::carryAlong(const std::vector<int>& vertexOf) const {
  MeshData out;
  out.source = in_.source, out.background = in_.background, out.comments = in_.comments;
  out.polygonsTriangulated = in_.polygonsTriangulated, out.stripTriangles = in_.stripTriangles;
  out.stripDegenerateSkipped = in_.stripDegenerateSkipped;
  out.nVertices = static_cast<int>(vertexOf.size());
  out.faces = faces_;
  if (!in_.positions.empty())
    for (int v : vertexOf) out.positions.push_back(in_.positions[origin_[v]]);
  for (const auto& [name, values] : in_.vertexProperties) {
    std::vector<double>& column = out.vertexProperties[name];
    for (int v : vertexOf) column.push_back(values[origin_[v]]);
  }
  if (in_.edges.empty()) return out;
  std::unordered_map<std::uint64_t, int> recordOf;
  for (size_t i = 0; i < in_.edges.size(); ++i) recordOf.emplace(repairPairKey(in_.edges[i].v0, in_.edges[i].v1), i);
  std::unordered_set<std::uint64_t> done;
  for (const auto& f : out.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      if (!done.insert(repairPairKey(a, b)).second) continue;
      const auto it = recordOf.find(repairPairKey(origin_[vertexOf[a]], origin_[vertexOf[b]]));
      if (it == recordOf.end())
        throw InputError(describeAt(in_.source, "edge (" + std::to_string(origin_[vertexOf[a]]) + ", " +
                                                    std::to_string(origin_[vertexOf[b]]) +
                                                    ") of a face has no length in the edge element"));
      out.edges.push_back({a, b, in_.edges[it->second].length});
      for (const auto& [name, values] : in_.edgeProperties) out.edgeProperties[name].push_back(values[it->second]);
    }
  return out;
}

// The fast test behind requireNoRepairNeeded, in arrays only (a 10⁶-face file is read in about a second; hash maps
// would cost several): no face that repeats a vertex or breaks the triangle inequality of its positions, no edge in
// more than two faces, one fan per vertex. Halfedges are bucketed by their smaller endpoint, each bucket sorted by the
// other; the corners are joined across every edge of two faces, and each vertex must see one root.
bool isManifoldAsGiven(const MeshData& d) {
  const int nF = static_cast<int>(d.faces.size()), nV = d.nVertices;
  for (const auto& f : d.faces) {
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) return false;
    if (d.positions.empty()) continue;
    double l[3];
    for (int k = 0; k < 3; ++k) l[k] = (d.positions[f[k]] - d.positions[f[(k + 1) % 3]]).norm();
    if (!isValidTriangle(d.background, l[0], l[1], l[2])) return false;
  }
  std::vector<int> start(nV + 1, 0);
  for (const auto& f : d.faces)
    for (int k = 0; k < 3; ++k) ++start[std::min(f[k], f[(k + 1) % 3]) + 1];
  for (int v = 0; v < nV; ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, int>> bucket(3 * static_cast<size_t>(nF));  // (other endpoint, halfedge)
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int h = 0; h < 3 * nF; ++h) {
    const int a = d.faces[h / 3][h % 3], b = d.faces[h / 3][(h % 3 + 1) % 3];
    bucket[fill[std::min(a, b)]++] = {std::max(a, b), h};
  }
  Fans fans(3 * nF);
  auto tipCorner = [](int h) { return 3 * (h / 3) + (h % 3 + 1) % 3; };
  for (int v = 0; v < nV; ++v) {
    std::sort(bucket.begin() + start[v], bucket.begin() + start[v + 1]);
    for (int i = start[v]; i < start[v + 1];) {
      int j = i;
      while (j < start[v + 1] && bucket[j].first == bucket[i].first) ++j;
      if (j - i > 2) return false;
      if (j - i == 2) {
        const int h = bucket[i].second, g = bucket[i + 1].second;
        if (d.faces[h / 3][h % 3] == d.faces[g / 3][g % 3]) {
          fans.join(h, g), fans.join(tipCorner(h), tipCorner(g));
        } else {
          fans.join(h, tipCorner(g)), fans.join(tipCorner(h), g);
        }
      }
      i = j;
    }
  }
  std::vector<int> rootOf(nV, -1);
  for (int c = 0; c < 3 * nF; ++c) {
    int& r = rootOf[d.faces[c / 3][c % 3]];
    const int root = fans.find(c);
    if (r >= 0 && r != root) return false;
    r = root;
  }
  return true;
}

}  // namespace

std::string RepairOptions::validate() const {
  if (!std::isfinite(mergeTolerance) || mergeTolerance > 1e-3)
    return "mergeTolerance must be finite and at most 1e-3 of the bounding-box diagonal (negative: no merging), found " +
           formatNumber(mergeTolerance);
  if (!std::isfinite(degenerateTolerance) || degenerateTolerance < 0 || degenerateTolerance > 1e-3)
    return "degenerateTolerance must be in [0, 1e-3], found " + formatNumber(degenerateTolerance);
  if (examples < 0) return "examples must be >= 0, found " + std::to_string(examples);
  return "";
}

bool RepairReport::neededForTriangulation() const {
  return degenerateFaces.count + duplicateFaces.count + nonManifoldEdges.count + pinchedVertices.count > 0;
}

bool RepairReport::changedAnything() const {
  return neededForTriangulation() || mergedVertices.count + reorientedFaces.count + unreferencedVertices.count > 0;
}

std::string RepairReport::summary() const {
  std::ostringstream s;
  auto step = [&](const char* what, const Step& st) {
    if (st.count == 0) return;
    s << what << ": " << st.count;
    for (size_t i = 0; i < st.examples.size(); ++i) s << (i == 0 ? " (" : ", ") << st.examples[i];
    if (!st.examples.empty()) s << (st.count > static_cast<int>(st.examples.size()) ? ", ...)" : ")");
    s << '\n';
  };
  step("merged duplicate vertices", mergedVertices);
  step("dropped degenerate faces", degenerateFaces);
  step("dropped duplicate faces", duplicateFaces);
  step("non-manifold edges cut into boundary", nonManifoldEdges);
  step("vertex fans given their own vertex", pinchedVertices);
  step("reoriented faces", reorientedFaces);
  step("unreferenced vertices removed", unreferencedVertices);
  return s.str();
}

MeshData repairMesh(const MeshData& data, const RepairOptions& options, RepairReport* report) {
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError("repair options: " + problem);
  if (!data.cornerEdges.empty())
    throw InputError(describeAt(data.source, "repair applies to polygon soups, not to a Δ-complex with edge_index"));
  if (data.nVertices <= 0 || data.faces.empty()) throw InputError(describeAt(data.source, "the mesh has no faces"));
  for (size_t f = 0; f < data.faces.size(); ++f)
    for (int v : data.faces[f])
      if (v < 0 || v >= data.nVertices)
        throw InputError(describeAt(data.source, faceText(static_cast<int>(f), data.faces[f]) + ": vertex index " +
                                                     std::to_string(v) + " out of range"));
  if (!data.positions.empty() && static_cast<int>(data.positions.size()) != data.nVertices)
    throw InputError(describeAt(data.source, "expected " + std::to_string(data.nVertices) + " positions, found " +
                                                 std::to_string(data.positions.size())));
  return MeshRepairer(data, options).run(report);
}

void requireNoRepairNeeded(const MeshData& data) {
  if (!data.cornerEdges.empty() || data.nVertices <= 0) return;
  for (const auto& f : data.faces)
    for (int v : f)
      if (v < 0 || v >= data.nVertices) return;  // toTriangulation names the index
  if (!data.positions.empty() && static_cast<int>(data.positions.size()) != data.nVertices) return;
  if (isManifoldAsGiven(data)) return;
  RepairOptions o;
  o.mergeTolerance = -1;
  o.degenerateTolerance = 0;  // exactly toTriangulation's criterion: the strict triangle inequality
  o.examples = 1;
  RepairReport r;
  try {
    repairMesh(data, o, &r);
  } catch (const InputError&) {
    return;  // repair would not help (every face degenerate, a non-orientable component): toTriangulation says why
  }
  if (!r.neededForTriangulation()) return;
  const std::pair<const RepairReport::Step*, const char*> steps[] = {{&r.degenerateFaces, "degenerate "},
                                                                      {&r.duplicateFaces, "duplicate "},
                                                                      {&r.nonManifoldEdges, "non-manifold "},
                                                                      {&r.pinchedVertices, "pinched "}};
  std::string first;
  for (const auto& [step, adjective] : steps)
    if (first.empty() && step->count > 0)
      first = adjective + step->examples[0] + (step->count > 1 ? " (" + std::to_string(step->count) + " in all)" : "");
  throw InputError(describeAt(data.source, "not a manifold triangle mesh: " + first +
                                               "; `--repair` would fix it (docs/cli.md#repair)"));
}

}  // namespace conformesh::intrinsic
