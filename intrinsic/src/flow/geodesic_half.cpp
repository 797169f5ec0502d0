// geodesic_half.cpp — the half of a mirror-symmetric closed triangulation (geodesic_half.h).
#include "flow/geodesic_half.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic::detail {
namespace {

enum Side : signed char { kUnknown = 0, kInput = 1, kMirror = 2, kSplit = 3, kTrapezoid = 4, kSplitLoop = 5 };

// cosh x − 1 and 1 − cos x without the cancellation near x = 0 (2 sinh²(x/2), 2 sin²(x/2)): the double's hyperbolic
// lengths go down to 10⁻⁸ (b9_mesh.off), where cosh x rounds to 1 and acosh of a rounded argument loses every digit.
double coshMinusOne(double x) {
  const double s = std::sinh(0.5 * x);
  return 2 * s * s;
}
double oneMinusCos(double x) {
  const double s = std::sin(0.5 * x);
  return 2 * s * s;
}

// The median from w of a triangle (v, v', w) with |wv| = a, |wv'| = b, |vv'| = c, to the midpoint of vv' (Stewart's
// theorem and its constant-curvature analogues, from the law of cosines at the midpoint on both sides:
// cosh m = (cosh a + cosh b)/(2 cosh(c/2)), cos m = (cos a + cos b)/(2 cos(c/2))), in the forms above that keep the
// relative accuracy of the Euclidean formula at small lengths: cosh m − 1 = (H(a) + H(b) − 2H(c/2))/(2 cosh(c/2)).
double medianLength(Background bg, double a, double b, double c) {
  switch (bg) {
    case Background::Euclidean:
      return std::sqrt(std::max(0.0, 0.5 * (a * a + b * b) - 0.25 * c * c));
    case Background::Hyperbolic: {
      const double h = (coshMinusOne(a) + coshMinusOne(b) - 2 * coshMinusOne(0.5 * c)) / (2 * std::cosh(0.5 * c));
      return 2 * std::asinh(std::sqrt(std::max(0.0, 0.5 * h)));
    }
    case Background::Spherical: {
      const double s = (oneMinusCos(a) + oneMinusCos(b) - 2 * oneMinusCos(0.5 * c)) / (2 * std::cos(0.5 * c));
      return 2 * std::asin(std::clamp(std::sqrt(std::max(0.0, 0.5 * s)), 0.0, 1.0));
    }
  }
  return 0;
}

// The other leg of a right triangle with hypotenuse c and leg a (Pythagoras; cosh c = cosh a cosh b; cos c = cos a cos
// b), as cosh b − 1 = 2 sinh((c − a)/2) sinh((c + a)/2) / cosh a (and its spherical analogue): no cancellation when
// the legs are small or b ≪ a.
double rightTriangleLeg(Background bg, double c, double a) {
  switch (bg) {
    case Background::Euclidean:
      return std::sqrt(std::max(0.0, (c - a) * (c + a)));
    case Background::Hyperbolic: {
      const double h = 2 * std::sinh(0.5 * (c - a)) * std::sinh(0.5 * (c + a)) / std::cosh(a);
      return 2 * std::asinh(std::sqrt(std::max(0.0, 0.5 * h)));
    }
    case Background::Spherical: {
      const double s = 2 * std::sin(0.5 * (c - a)) * std::sin(0.5 * (c + a)) / std::cos(a);
      return 2 * std::asin(std::clamp(std::sqrt(std::max(0.0, 0.5 * s)), 0.0, 1.0));
    }
  }
  return 0;
}

ConvergenceError notSymmetric(int f, const std::string& what) {
  return ConvergenceError(
      "geodesic boundary from the double: the double's triangulation is not mirror-symmetric at "
      "its face " +
      std::to_string(f) + " (" + what + ")");
}

// Per face: its side, and for a face of a trapezoid its diagonal (the halfedge shared with the quad's other face).
struct FaceSides {
  std::vector<signed char> side;
  std::vector<int> diagonal;    // kTrapezoid faces only
  std::vector<char> firstHalf;  // kSplitLoop faces only: which half of the bisected face is the input's
};

// The diagonal of a face of a trapezoid (a, b, b', a') of interior vertices: its edge between the two sides that does
// not join a vertex to its mirror image; −1 when there is none.
int trapezoidDiagonal(const HalfedgeMesh& m, const std::vector<int>& mirror, int nInput, int f) {
  for (int k = 0; k < 3; ++k) {
    const int h = HalfedgeMesh::halfedge(f, k), p = m.tail(h), q = m.tip(h);
    if (mirror[p] == p || mirror[q] == q || mirror[p] == q) continue;
    if ((p < nInput) != (q < nInput)) return h;
  }
  return -1;
}

// Per face: kInput / kMirror when it has a vertex of that side only, kSplit for (v, v', w), kTrapezoid for half of a
// quad (a, b, b', a'), kUnknown when all three vertices are on the boundary (sidesFromCentroids decides).
FaceSides classifyFaces(const HalfedgeMesh& m, const std::vector<int>& mirror, int nInput) {
  FaceSides sides{std::vector<signed char>(m.nFaces(), kUnknown), std::vector<int>(m.nFaces(), -1),
                  std::vector<char>(m.nFaces(), 0)};
  for (int f = 0; f < m.nFaces(); ++f) {
    int input = 0, copy = 0;
    for (int k = 0; k < 3; ++k) {
      const int v = m.faceVertex(f, k);
      input += v < nInput && mirror[v] != v;
      copy += v >= nInput;
    }
    signed char& side = sides.side[f];
    if (input + copy == 3 && input > 0 && copy > 0) {
      side = kTrapezoid;  // half of a quad (a, b, b', a'): checked when it is split
      sides.diagonal[f] = trapezoidDiagonal(m, mirror, nInput, f);
      if (sides.diagonal[f] < 0) throw notSymmetric(f, "a face of both sides without a diagonal of a trapezoid");
    } else if (input > 0 && copy > 0) {
      for (int k = 0; k < 3; ++k) {
        const int v = m.faceVertex(f, k), w = m.faceVertex(f, (k + 2) % 3);
        if (v < nInput && mirror[v] != v && m.faceVertex(f, (k + 1) % 3) != mirror[v] && w != mirror[v])
          throw notSymmetric(f, "an interior vertex beside a copy that is not its mirror image");
      }
      side = kSplit;
    } else if (input > 0) {
      side = kInput;
    } else if (copy > 0) {
      side = kMirror;
    }
  }
  return sides;
}

// The faces that lie on one side (no vertex of the other side) take the side of their centroid's image under the
// double's flip log: a face of the double's T0 below `inputFaces` is the input's. Vertex patterns alone cannot decide
// a face of boundary vertices, nor tell the sides across an edge of a multi-edge or a loop (elephant-with-holes.off:
// a loop around a three-edge hole); no face off the mirror crosses it (an edge that did would meet its mirror image),
// so its centroid decides. Throws when a face with a vertex of one side maps to the other.
void sidesFromCentroids(const HalfedgeMesh& m, const FlowCorrespondence& log, int inputFaces,
                        std::vector<signed char>& side) {
  std::vector<FacePoint> centroids;
  std::vector<int> which;
  for (int f = 0; f < m.nFaces(); ++f)
    if (side[f] == kInput || side[f] == kMirror || side[f] == kUnknown) {
      centroids.push_back(FacePoint{f, {1.0 / 3, 1.0 / 3, 1.0 / 3}});
      which.push_back(f);
    }
  const std::vector<FacePoint> images = log.mapToInput(m, centroids);
  for (std::size_t i = 0; i < images.size(); ++i) {
    const signed char found = images[i].face < inputFaces ? kInput : kMirror;
    if (side[which[i]] != kUnknown && side[which[i]] != found)
      throw notSymmetric(which[i], "its vertices are on one side and its centroid maps to the other");
    side[which[i]] = found;
  }
}

// The loop face f of self-symmetric loop hl = p → p with apex w off the mirror and the face across its edge to w that
// holds w' (findSymmetricLoopFaces): both kTrapezoid, their shared edge the diagonal. Throws when neither face across
// f's other edges holds w' (no trapezoid: the triangulation is not symmetric there).
void markLoopTrapezoid(const HalfedgeMesh& m, const std::vector<int>& mirror, int hl, FaceSides& sides) {
  const int f = HalfedgeMesh::face(hl), w = m.tip(HalfedgeMesh::next(hl));
  for (const int h : {HalfedgeMesh::next(hl), HalfedgeMesh::prev(hl)}) {
    const int g = HalfedgeMesh::face(m.twin(h));
    bool holdsMirror = false;
    for (int k = 0; k < 3; ++k) holdsMirror = holdsMirror || m.faceVertex(g, k) == mirror[w];
    if (!holdsMirror || g == f) continue;
    sides.side[f] = sides.side[g] = kTrapezoid;
    sides.diagonal[f] = h;
    sides.diagonal[g] = m.twin(h);
    return;
  }
  throw notSymmetric(f, "a loop around the mirror whose face has an apex off the mirror and no trapezoid");
}

// A loop hl = p → p at a boundary vertex is self-symmetric — it goes once around a short hole's neck and the mirror
// crosses it at its midpoint — when that midpoint maps onto the mirror of the double's T0 (an edge of T0 between a
// face of the input and one of the copy; elephant-with-holes.off). Vertex patterns cannot see it: both ends are on
// the boundary. The reflection keeps each side of such a loop, so the face (p, p, w) on a side is either
// self-symmetric — w on the boundary, the face bisected from w to the loop's midpoint (kSplitLoop; the half kept,
// (p, mid, w) or (mid, p, w), the one whose centroid maps to the input's side, `firstHalf`) — or, w off the mirror,
// one face of a trapezoid (w, p, p, w') whose parallel sides are the loop and the crossing edge w–w' and whose
// diagonal, chosen by the flips at a tie, is the edge that f shares with the face holding w' (b9_mesh.off).
void findSymmetricLoopFaces(const IntrinsicTriangulation& doubled, const std::vector<int>& mirror,
                            const FlowCorrespondence& log, const HalfedgeMesh& doubleInput, int inputFaces,
                            FaceSides& sides) {
  constexpr double kOnEdge = 1e-6;  // barycentric: far above the replay's round-off, far below a generic distance
  const HalfedgeMesh& m = doubled.mesh;
  std::vector<int> loops;
  std::vector<FacePoint> probes;  // per candidate: the loop's midpoint, the centroid of its first half
  for (int f = 0; f < m.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int hl = HalfedgeMesh::halfedge(f, k), p = m.tail(hl);
      if (m.tip(hl) != p || mirror[p] != p) continue;
      FacePoint mid{f, {0, 0, 0}}, first{f, {0, 0, 0}};
      mid.bary[k] = mid.bary[(k + 1) % 3] = 0.5;
      first.bary[k] = 0.5;  // (p_c0, mid, w): the corners' thirds, mid = half c0 + half c1
      first.bary[(k + 1) % 3] = 1.0 / 6;
      first.bary[(k + 2) % 3] = 1.0 / 3;
      loops.push_back(hl);
      probes.push_back(mid);
      probes.push_back(first);
    }
  if (loops.empty()) return;
  const std::vector<FacePoint> images = log.mapToInput(m, probes);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const FacePoint& q = images[2 * i];
    const int k = static_cast<int>(std::min_element(q.bary.begin(), q.bary.end()) - q.bary.begin());
    const int across = HalfedgeMesh::face(doubleInput.twin(HalfedgeMesh::halfedge(q.face, (k + 1) % 3)));
    if (q.bary[k] > kOnEdge || (q.face < inputFaces) == (across < inputFaces)) continue;
    const int hl = loops[i], f = HalfedgeMesh::face(hl), w = m.tip(HalfedgeMesh::next(hl));
    if (mirror[w] == w) {
      sides.side[f] = kSplitLoop;
      sides.firstHalf[f] = images[2 * i + 1].face < inputFaces;
      continue;
    }
    markLoopTrapezoid(m, mirror, hl, sides);
  }
}

// The half assembled face by face: kept faces and edges of the double, crossing edges halved once (shared by the faces
// on both of their sides), new edges with their lengths.
class DoubleHalver {
 public:
  DoubleHalver(const IntrinsicTriangulation& doubled, const std::vector<int>& mirror, int nInput)
      : d_(doubled), m_(doubled.mesh), mirror_(mirror), nInput_(nInput), idOfEdge_(m_.nEdges(), -1) {}

  void addKeptFace(int f) {
    faces_.push_back({m_.faceVertex(f, 0), m_.faceVertex(f, 1), m_.faceVertex(f, 2)});
    ids_.push_back(
        {keep(HalfedgeMesh::halfedge(f, 0)), keep(HalfedgeMesh::halfedge(f, 1)), keep(HalfedgeMesh::halfedge(f, 2))});
  }
  void addSplitFace(int f);
  void addBisectedHalf(int hc, bool keepTail, int owner);
  void addTrapezoid(int f, int hd);
  void addSplitLoop(int f, bool firstHalf);
  GeodesicHalf build();

 private:
  bool isInput(int v) const { return v < nInput_ && mirror_[v] != v; }
  int keep(int h);
  std::array<int, 2> split(int hc, int v);
  int newEdge(double length) {
    lengths_.push_back(length);
    return static_cast<int>(lengths_.size()) - 1;
  }
  void noteAsymmetry(double a, double b) {
    out_.asymmetry = std::max(out_.asymmetry, std::abs(a - b) / std::max(a, b));
  }

  const IntrinsicTriangulation& d_;
  const HalfedgeMesh& m_;
  const std::vector<int>& mirror_;
  const int nInput_;
  GeodesicHalf out_;
  std::vector<std::array<int, 3>> faces_, ids_;
  std::vector<double> lengths_;                    // per edge id of the half
  std::vector<int> idOfEdge_;                      // kept edges of the double → their id
  std::map<int, std::array<int, 2>> splitOfEdge_;  // crossing edge → (its midpoint vertex, the id of its input half)
  std::vector<char> trapezoidDone_;
};

int DoubleHalver::keep(int h) {
  const int e = m_.edge(h);
  if (idOfEdge_[e] < 0) idOfEdge_[e] = newEdge(d_.edgeLengths[e]);
  return idOfEdge_[e];
}

// The midpoint of crossing edge v–v' (a new boundary vertex) and the id of the half v–midpoint.
std::array<int, 2> DoubleHalver::split(int hc, int v) {
  auto [it, fresh] = splitOfEdge_.try_emplace(m_.edge(hc), std::array<int, 2>{-1, -1});
  if (fresh) {
    it->second = {nInput_ + static_cast<int>(out_.splitFrom.size()), newEdge(0.5 * d_.length(hc))};
    out_.splitFrom.push_back(v);
    out_.splitHalfedge.push_back(hc);
  }
  return it->second;
}

// The face of crossing halfedge hc = X → Y with apex w, bisected from w to hc's midpoint (the median, by symmetry the
// mirror's segment): the half (X, mid, w) when `keepTail`, else (mid, Y, w); `owner` the input vertex it is charged to.
void DoubleHalver::addBisectedHalf(int hc, bool keepTail, int owner) {
  const int hn = HalfedgeMesh::next(hc), hp = HalfedgeMesh::prev(hc);
  const int x = m_.tail(hc), y = m_.tip(hc), w = m_.tip(hn);
  const double a = d_.length(hp), b = d_.length(hn), c = d_.length(hc);
  noteAsymmetry(a, b);
  const auto [mid, halfId] = split(hc, owner);
  const int median = newEdge(medianLength(d_.background, a, b, c));
  if (keepTail) {
    faces_.push_back({x, mid, w});
    ids_.push_back({halfId, median, keep(hp)});
  } else {
    faces_.push_back({mid, y, w});
    ids_.push_back({halfId, keep(hn), median});
  }
}

// A face (v, v', w), w on the boundary: its input half (v, midpoint, w), split along the median from w.
void DoubleHalver::addSplitFace(int f) {
  int k0 = 0;
  while (!isInput(m_.faceVertex(f, k0))) ++k0;
  const int h0 = HalfedgeMesh::halfedge(f, k0), v = m_.tail(h0);
  const int hc = m_.tip(h0) == mirror_[v] ? h0 : HalfedgeMesh::prev(h0);  // v → v', else v' → v
  ++out_.splitFaces;
  addBisectedHalf(hc, m_.tail(hc) == v, v);
}

// Two crossing edges a–a', b–b' that bound one quad (a, b, b', a') — an isosceles trapezoid, always cocircular, so
// the Delaunay flips pick one of its diagonals a–b' or b–a' (`hd`, a halfedge of f), neither mirror-symmetric. One
// crossing side may be a self-symmetric loop at a boundary vertex b = b' (findSymmetricLoopFaces). Its input half is
// the quad (a, b, m_b, m_a) with right angles at the midpoints, triangulated (a, b, m_b), (a, m_b, m_a): |a m_b| is
// the median from a in the triangle (a, b, b') (whose side a–b' is the diagonal when that was chosen, else found from
// the other triangle by symmetry), |m_a m_b| the other leg of the right triangle (a, m_a, m_b).
void DoubleHalver::addTrapezoid(int f, int hd) {
  if (trapezoidDone_.empty()) trapezoidDone_.assign(m_.nEdges(), 0);
  if (trapezoidDone_[m_.edge(hd)]) return;
  trapezoidDone_[m_.edge(hd)] = 1;
  // The quad's cycle P → S → Q → R around the diagonal P → Q of (P, Q, R) and (Q, P, S), with its halfedges.
  const int t = m_.twin(hd);
  const std::array<int, 4> cycle{m_.tail(hd), m_.tip(HalfedgeMesh::next(t)), m_.tip(hd),
                                 m_.tip(HalfedgeMesh::next(hd))};
  const std::array<int, 4> sideH{HalfedgeMesh::next(t), HalfedgeMesh::prev(t), HalfedgeMesh::next(hd),
                                 HalfedgeMesh::prev(hd)};  // cycle[i] → cycle[i+1]
  // The side a → b of the input's half: followed by the crossing side b → b' and preceded by a' → a, with a or b an
  // input vertex off the mirror (the other may be the boundary vertex of a loop side).
  int r = 0;
  while (r < 4 && !((isInput(cycle[r]) || isInput(cycle[(r + 1) % 4])) &&
                    mirror_[cycle[(r + 1) % 4]] == cycle[(r + 2) % 4] && mirror_[cycle[r]] == cycle[(r + 3) % 4]))
    ++r;
  if (r == 4) throw notSymmetric(f, "a trapezoid without an input side between two crossing sides");
  const int a = cycle[r], b = cycle[(r + 1) % 4];
  const int hab = sideH[r], hb = sideH[(r + 1) % 4], hcopy = sideH[(r + 2) % 4], ha = sideH[(r + 3) % 4];
  noteAsymmetry(d_.length(hab), d_.length(hcopy));
  ++out_.trapezoids;
  // |a b'|: the diagonal when it is a–b', else |b a'| (its mirror image).
  const double diagonal = d_.length(hd);
  const double bb = d_.length(hb), aa = d_.length(ha), ab = d_.length(hab);
  const double toMb = medianLength(d_.background, ab, diagonal, bb);
  const double la = 0.5 * aa;
  const auto [mb, halfB] = split(hb, b);
  const auto [ma, halfA] = split(ha, a);
  const int diag = newEdge(toMb), rim = newEdge(rightTriangleLeg(d_.background, toMb, la));
  faces_.push_back({a, b, mb});
  ids_.push_back({keep(hab), halfB, diag});
  faces_.push_back({a, mb, ma});
  ids_.push_back({diag, rim, halfA});
}

// A face (p, p, w) bisected from w to the midpoint of its loop hl = p(c0) → p(c1); the half kept is (p(c0), mid, w)
// when `firstHalf`, else (mid, p(c1), w).
void DoubleHalver::addSplitLoop(int f, bool firstHalf) {
  int hl = HalfedgeMesh::halfedge(f, 0);
  while (m_.tail(hl) != m_.tip(hl)) hl = HalfedgeMesh::next(hl);
  ++out_.splitLoops;
  addBisectedHalf(hl, firstHalf, m_.tail(hl));
}

GeodesicHalf DoubleHalver::build() {
  const int nVertices = nInput_ + static_cast<int>(out_.splitFrom.size());
  try {
    out_.half.mesh = HalfedgeMesh::fromFaces(faces_, nVertices, "the half of the double", nullptr, ids_);
  } catch (const InputError& e) {
    throw ConvergenceError(std::string("geodesic boundary from the double: ") + e.what());
  }
  out_.half.background = d_.background;
  out_.half.edgeLengths.assign(out_.half.mesh.nEdges(), 0.0);
  for (std::size_t f = 0; f < faces_.size(); ++f)
    for (int k = 0; k < 3; ++k)
      out_.half.edgeLengths[out_.half.mesh.edge(HalfedgeMesh::halfedge(static_cast<int>(f), k))] = lengths_[ids_[f][k]];
  try {
    validateLengths(out_.half, "the half of the double");
  } catch (const InputError& e) {
    throw ConvergenceError(std::string("geodesic boundary from the double: ") + e.what());
  }
  return std::move(out_);
}

}  // namespace

GeodesicHalf halveSymmetricDouble(const IntrinsicTriangulation& doubled, const std::vector<int>& mirror, int nInput,
                                  const FlowCorrespondence& log, const HalfedgeMesh& doubleInput, int inputFaces) {
  FaceSides sides = classifyFaces(doubled.mesh, mirror, nInput);
  findSymmetricLoopFaces(doubled, mirror, log, doubleInput, inputFaces, sides);
  sidesFromCentroids(doubled.mesh, log, inputFaces, sides.side);
  DoubleHalver halver(doubled, mirror, nInput);
  for (int f = 0; f < doubled.mesh.nFaces(); ++f) {
    const signed char side = sides.side[f];
    if (side == kInput) halver.addKeptFace(f);
    if (side == kSplit) halver.addSplitFace(f);
    if (side == kTrapezoid) halver.addTrapezoid(f, sides.diagonal[f]);
    if (side == kSplitLoop) halver.addSplitLoop(f, sides.firstHalf[f]);
  }
  return halver.build();
}

}  // namespace conformesh::intrinsic::detail
