// pull_back.cpp — output vertices and edges of the uniformized route taken back through the input faces
// (pull_back.h).
#include "pipeline/pull_back.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <Eigen/LU>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/trace/geodesic_trace.h"

namespace conformesh::refine::detail {

using namespace conformesh::intrinsic;

ImagePathPullBack::ImagePathPullBack(const SubdividedInput& input, const Uniformization& u, const RefineResult& refined,
                                     int extraBisections)
    : input_(input),
      u_(u),
      refined_(refined),
      extraBisections_(extraBisections),
      n0_(input.t0.mesh.nVertices()),
      inputSignposts_(initialSignposts(u.uniform)),
      model_(u.uniform.background) {
  // T0*'s own vertices other than T0's would be mapped through a correspondence of 0 faces (uniformization.h).
  const std::string gap = correspondenceUnavailable(u);
  if (!gap.empty()) throw ConvergenceError("pull-back: " + gap + "; no correspondence maps them to the input");
}

void ImagePathPullBack::run(MeshRemeshResult& out) {
  out.lambda = refined_.lambda;
  mapVertices(out);
  traceEdges();
  mapPieceEnds();
  resolvePieces(out);
  const std::vector<double> lengths = developLengths(out);
  out.pathLength = pathLength_;
  out.mesh.mesh = refined_.triangulation.mesh;
  out.mesh.background = Background::Euclidean;
  out.mesh.edgeLengths = lengths;
  if (const int flips = untangleFolds(out))
    out.notices.push_back("pull-back: " + std::to_string(flips) +
                          " output edges flipped where the straight chords of bent image paths folded a triangle over "
                          "a vertex");
  validateLengths(out.mesh, "remeshed surface (developed image-path lengths)");
}

// Input vertices are themselves; inserted ones go through the correspondence (boundary caps clamped), then through
// the subdivision to their input face.
void ImagePathPullBack::mapVertices(MeshRemeshResult& out) {
  const HalfedgeMesh& m0 = input_.t0.mesh;
  const int n1 = refined_.triangulation.mesh.nVertices();
  out.location.resize(n1);
  vertexImage_.resize(n1);
  std::vector<FacePoint> onStar;
  for (int v = n0_; v < n1; ++v) {
    const Eigen::Vector3d b = clampToFace(refined_.locations[v].bary);
    onStar.push_back({refined_.locations[v].face, {b[0], b[1], b[2]}});
  }
  const std::vector<FacePoint> onInput = u_.correspondence.mapToInput(u_.uniform.mesh, onStar);
  for (int v = 0; v < n1; ++v) vertexImage_[v] = v < n0_ ? vertexPoint(m0, v) : toPoint(onInput[v - n0_]);
  placeInnerArcsOnChords();
  const auto& parentCorner = input_.parentCorner;
  for (int v = 0; v < n1; ++v) {
    const Point& p = vertexImage_[v];
    const Eigen::Vector3d b =
        p.bary[0] * parentCorner[p.face][0] + p.bary[1] * parentCorner[p.face][1] + p.bary[2] * parentCorner[p.face][2];
    out.location[v] = {input_.parentFace[p.face], {b[0], b[1], b[2]}};
  }
}

// Boundary vertices split on a boundary circle that bulges INTO the domain (a hole's circle of a circle domain: its
// chords lie in the hole) sit inside a boundary face of T0*, not beyond its chord, so clampToFace leaves them there
// and they would map into the interior of an input face, cutting the arc's cap off the output (holes.off: 96 boundary
// vertices, area −4.4e-4 relative). Like the caps beyond a chord, such an arc is mapped onto its chord: each vertex at
// its fraction of the arc's length between the chord's ends (the output's boundary lengths on T1*), which keeps the
// vertices' order along the chord. A vertex that is beyond or on its chord (a coordinate ≤ 0) keeps clampToFace's foot.
void ImagePathPullBack::placeInnerArcsOnChords() {
  const HalfedgeMesh& m0 = input_.t0.mesh;
  const HalfedgeMesh& m1 = refined_.triangulation.mesh;
  std::vector<int> arc;
  for (int h = 0; h < m1.nHalfedges(); ++h) {
    if (m1.twin(h) != kInvalid || m1.tail(h) >= n0_ || m1.tip(h) < n0_) continue;
    const int a = m1.tail(h);
    arc.clear();
    std::vector<double> at;  // arc length from a to each vertex of `arc`
    double length = 0;
    int g = h;
    for (; m1.tip(g) >= n0_; g = m1.nextBoundaryHalfedge(g)) {
      length += refined_.triangulation.length(g);
      arc.push_back(m1.tip(g));
      at.push_back(length);
    }
    length += refined_.triangulation.length(g);
    const int chord = m0.vertexHalfedge(a);
    if (m0.twin(chord) != kInvalid || m0.tip(chord) != m1.tip(g)) continue;  // not one T0 boundary side: left as is
    for (std::size_t i = 0; i < arc.size(); ++i) {
      const Eigen::Vector3d& b = refined_.locations[arc[i]].bary;
      if (!(b.minCoeff() > 0)) continue;
      Point p;
      p.face = HalfedgeMesh::face(chord);
      p.bary[chord % 3] = 1 - at[i] / length;
      p.bary[(chord + 1) % 3] = at[i] / length;
      vertexImage_[arc[i]] = p;
    }
  }
}

// Each output edge traced across T0*, one piece per T0* face it crosses.
void ImagePathPullBack::traceEdges() {
  const HalfedgeMesh& m1 = refined_.triangulation.mesh;
  pieces_.reserve(2 * m1.nEdges());
  firstPiece_.assign(m1.nEdges() + 1, 0);
  std::vector<EdgeCrossing> crossings;
  for (int e = 0; e < m1.nEdges(); ++e) {
    firstPiece_[e] = static_cast<int>(pieces_.size());
    traceEdge(e, crossings);
  }
  firstPiece_[m1.nEdges()] = static_cast<int>(pieces_.size());
}

// The geodesic of output edge e from its tail: from an input vertex in its signpost direction (a direction just
// outside a boundary vertex's fan is snapped onto the nearer boundary edge), else from its point on T0*. A trace
// ending beyond a boundary chord, in its cap, ends at its foot there (the cap maps onto its chord).
void ImagePathPullBack::traceEdge(int e, std::vector<EdgeCrossing>& crossings) {
  const IntrinsicTriangulation& star = u_.uniform;
  const HalfedgeMesh& m1 = refined_.triangulation.mesh;
  const int h = m1.edgeHalfedge(e), a = m1.tail(h), b = m1.tip(h);
  const double theta = refined_.signposts.angle[h], length = refined_.triangulation.length(h);
  TraceOptions options;
  options.unfolding = Unfolding::CornerAngle;
  options.outward = OutwardDirection::FollowBoundary;
  options.crossings = &crossings;
  crossings.clear();
  TraceResult r;
  int face;
  Eigen::Vector3d entry = Eigen::Vector3d::Zero();
  try {
    if (a < n0_) {
      r = traceFromVertex(star, inputSignposts_, model_, a, theta, length, kInvalid, options);
      face = HalfedgeMesh::face(r.startHalfedge);
      entry[r.startHalfedge % 3] = 1;
    } else {
      const InputLocation& from = refined_.locations[a];
      face = from.face;
      const std::array<Vec3, 3> P = layoutFace(star, model_, face);
      const Vec3 s = model_.fromBarycentric(P[0], P[1], P[2], from.bary);
      const Vec3 t = model_.exp(s, model_.direction(s, theta), length);
      entry = clampToFace(from.bary);
      r = traceFromPoint(star, model_, face, P, s, t, options);
    }
  } catch (const ConvergenceError& error) {
    throw ConvergenceError("mesh remesh: the trace of output edge " + std::to_string(e) + ": " + error.what());
  }
  for (const EdgeCrossing& c : crossings) {
    pieces_.push_back({e, face, entry, c.bary, {}, {}, 0});
    const int k = c.halfedge % 3, g = star.mesh.twin(c.halfedge), kg = g % 3;
    face = HalfedgeMesh::face(g);
    entry = Eigen::Vector3d::Zero();
    entry[kg] = c.bary[(k + 1) % 3];
    entry[(kg + 1) % 3] = c.bary[k];
  }
  pieces_.push_back({e, r.face, entry, clampToFace(r.bary), {}, {}, 0});
  // The end is the vertex's own image (an input vertex exactly).
  Piece& last = pieces_.back();
  if (b < n0_)
    for (int k = 0; k < 3; ++k)
      if (star.mesh.faceVertex(last.starFace, k) == b) last.b = Eigen::Vector3d::Unit(k);
}

// The pieces' ends on T0, through the correspondence in one pass.
void ImagePathPullBack::mapPieceEnds() {
  const HalfedgeMesh& m1 = refined_.triangulation.mesh;
  std::vector<FacePoint> ends;
  ends.reserve(2 * pieces_.size());
  for (const Piece& p : pieces_)
    for (const Eigen::Vector3d* b : {&p.a, &p.b}) ends.push_back({p.starFace, {(*b)[0], (*b)[1], (*b)[2]}});
  const std::vector<FacePoint> images = u_.correspondence.mapToInput(u_.uniform.mesh, ends);
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    pieces_[i].imageA = toPoint(images[2 * i]);
    pieces_[i].imageB = toPoint(images[2 * i + 1]);
  }
  for (int e = 0; e < m1.nEdges(); ++e) {
    const int h = m1.edgeHalfedge(e);
    // The ends are the vertices' own images: exact for input vertices, and for a vertex on a boundary circle its
    // foot on its own chord (the trace may reach its cap across a neighbouring chord).
    pieces_[firstPiece_[e]].imageA = vertexImage_[m1.tail(h)];
    pieces_[firstPiece_[e + 1] - 1].imageB = vertexImage_[m1.tip(h)];
  }
}

// Bisects pieces whose image ends are neither in one input face nor in two adjacent ones, all together per round
// (one pass of the correspondence per round). Each halving shortens the image by about half; a piece still
// unresolved after 60 (below 1e-18 of its edge) means a degenerate input. After 50 halvings a piece is 2⁻⁵⁰ ≈ 1e-15
// of its edge: ends whose faces share only a vertex are then taken to pass through it (the path cannot be told from
// one through the vertex in double precision).
void ImagePathPullBack::resolvePieces(MeshRemeshResult& out) {
  constexpr int kTinyRound = 50;
  const int nEdges = refined_.triangulation.mesh.nEdges();
  pathLength_.assign(nEdges, 0.0);
  out.edgePieces.assign(nEdges, 0);
  records_.reserve(pieces_.size());
  for (std::size_t i = 0; i < pieces_.size(); ++i) pieces_[i].order = static_cast<int>(i);
  std::vector<Piece> pending = std::move(pieces_);
  for (int round = 0; !pending.empty(); ++round) {
    std::vector<Piece> unresolved;
    for (const Piece& p : pending) {
      Resolved r;
      if (p.depth >= extraBisections_ && resolvePiece(input_.t0, p.imageA, p.imageB, round >= kTinyRound, r)) {
        pathLength_[p.edge] += r.length;
        out.edgePieces[p.edge] += r.crossing != kInvalid || r.viaCorner >= 0 ? 2 : 1;
        if (r.crossing != kInvalid || r.viaCorner >= 0) ++out.inputEdgeCrossings;
        records_.push_back({p.edge, p.order, p.t, r});
        continue;
      }
      if (round >= 60)
        throw ConvergenceError("mesh remesh: the image of output edge " + std::to_string(p.edge) +
                               " could not be followed across the input faces (input faces " +
                               std::to_string(p.imageA.face) + " and " + std::to_string(p.imageB.face) +
                               " after 60 halvings): degenerate input");
      unresolved.push_back(p);
    }
    if (unresolved.empty()) break;
    pending = bisect(unresolved);
  }
  for (int n : out.edgePieces) out.pathPieces += n;
}

// Halves each piece on its T0* segment (projective coordinates are affine on it) and maps the midpoints to T0.
std::vector<ImagePathPullBack::Piece> ImagePathPullBack::bisect(const std::vector<Piece>& unresolved) const {
  std::vector<Piece> split;
  split.reserve(2 * unresolved.size());
  for (const Piece& p : unresolved) {
    const Eigen::Vector3d mid = 0.5 * (p.a + p.b);
    const double half = std::ldexp(1.0, -(p.depth + 1));
    split.push_back({p.edge, p.starFace, p.a, mid, p.imageA, {}, p.depth + 1, p.order, p.t});
    split.push_back({p.edge, p.starFace, mid, p.b, {}, p.imageB, p.depth + 1, p.order, p.t + half});
  }
  std::vector<FacePoint> mids(split.size() / 2);
  for (std::size_t i = 0; i < mids.size(); ++i) {
    const Eigen::Vector3d& b = split[2 * i].b;
    mids[i] = {split[2 * i].starFace, {b[0], b[1], b[2]}};
  }
  const std::vector<FacePoint> images = u_.correspondence.mapToInput(u_.uniform.mesh, mids);
  for (std::size_t i = 0; i < mids.size(); ++i) split[2 * i].imageB = split[2 * i + 1].imageA = toPoint(images[i]);
  return split;
}

// Develops each edge's path (records in path order) and measures its ends' distance in the plane: the output length.
std::vector<double> ImagePathPullBack::developLengths(MeshRemeshResult& out) {
  const HalfedgeMesh& m0 = input_.t0.mesh;
  std::sort(records_.begin(), records_.end(),
            [](const Record& x, const Record& y) { return x.order != y.order ? x.order < y.order : x.t < y.t; });
  std::vector<double> lengths(refined_.triangulation.mesh.nEdges(), 0.0);
  Development dev(input_.t0);
  charts_.assign(lengths.size(), EdgeChart{});
  for (std::size_t i = 0; i < records_.size();) {
    const int e = records_[i].edge;
    dev.start(records_[i].r.faceA);
    const int start = dev.face();
    const Eigen::Vector2d from = dev.point(records_[i].r.a);
    Eigen::Vector3d at = records_[i].r.a;  // the current point, in the current face
    for (; i < records_.size() && records_[i].edge == e; ++i) {
      const Resolved& r = records_[i].r;
      if (!dev.moveTo(r.faceA, at, -1))
        throw ConvergenceError("mesh remesh: the image path of output edge " + std::to_string(e) +
                               " jumps from input face " + std::to_string(dev.face()) + " to face " +
                               std::to_string(r.faceA) + ", which shares no side or corner with it");
      if (r.crossing != kInvalid) dev.across(r.crossing % 3);
      if (r.viaCorner >= 0 && !dev.moveTo(r.faceB, Eigen::Vector3d::Unit(r.viaCorner), r.viaCorner))
        throw ConvergenceError("mesh remesh: the image path of output edge " + std::to_string(e) +
                               " passes input vertex " + std::to_string(m0.faceVertex(r.faceA, r.viaCorner)) +
                               " between faces that its fan does not join");
      at = r.b;
    }
    lengths[e] = (dev.point(at) - from).norm();
    charts_[e] = chartOf(e, start, from, dev, at);
    if (lengths[e] > 0) out.maxBendExcess = std::max(out.maxBendExcess, pathLength_[e] / lengths[e] - 1);
  }
  return lengths;
}

// The chart of output edge e (EdgeChart) from its development: `from` its tail's image in the canonical layout of
// face `startFace`, `end` the development at its last face, where `at` is its tip's image.
ImagePathPullBack::EdgeChart ImagePathPullBack::chartOf(int e, int startFace, const Eigen::Vector2d& from,
                                                        const Development& end, const Eigen::Vector3d& at) const {
  // The motion taking the canonical layout of d's current face onto d's layout of it (corner 0 at 0, 1 on the x axis).
  const auto layoutMotion = [](const Development& d) {
    const Eigen::Vector2d u = (d.corner(1) - d.corner(0)).normalized();
    PlaneMotion p;
    p.R << u.x(), -u.y(), u.y(), u.x();
    p.t = d.corner(0);
    return p;
  };
  const HalfedgeMesh& m1 = refined_.triangulation.mesh;
  const int h = m1.edgeHalfedge(e), a = m1.tail(h), b = m1.tip(h);
  EdgeChart c;
  c.tail = a;
  Development toTip = end;
  if (b >= n0_ && !toTip.moveTo(vertexImage_[b].face, at, -1)) return c;
  c.motion = layoutMotion(toTip);  // chart(b) → the canonical layout of startFace
  c.pa = from;
  c.pb = end.point(at);
  if (a >= n0_) {
    Development fromTail(input_.t0);
    fromTail.start(vertexImage_[a].face);
    if (!fromTail.moveTo(startFace, vertexImage_[a].bary, -1)) return c;
    const PlaneMotion toA = layoutMotion(fromTail);  // startFace's canonical layout → chart(a)
    c.motion = toA * c.motion;
    c.pa = toA(c.pa);
    c.pb = toA(c.pb);
  }
  c.ok = true;
  return c;
}

// Each output edge's length is the straight chord of its image path, which bends at the input edges (the
// correspondence is projective per face, not across them). Where a path bends past an output vertex, the straight
// chord passes on its other side, and the output triangle between them is folded over: its lengths are a triangle's,
// but laid out on T0 it is inverted, the angle sums at its corners are off and the area is not the input's
// (reference_tetrahedron at --eps-rel 0.05: triangle (124, 341, 804), vertex 804 at 0.008 of its face's height from
// input edge 1–3; angle sums off by −0.750, +0.392, +0.358 rad; area +1.0e-3 relative). Each triangle is laid out on T0
// in the chart of one of its inserted vertices (from its edges' developments); an inverted one is undone by flipping
// the edge whose flip leaves both new triangles positive, its new length measured in the same chart (the quad holds no
// input vertex inside: both triangles are output triangles). Returns the number of flips.
int ImagePathPullBack::untangleFolds(MeshRemeshResult& out) {
  HalfedgeMesh& m = out.mesh.mesh;
  const auto chart = [&](int h) -> const EdgeChart& { return charts_[m.edge(h)]; };
  const auto forward = [&](int h) { return m.tail(h) == chart(h).tail; };
  // Of halfedge h: its tail's and tip's images in chart(tail), its tail's in chart(tip), motion chart(tip) →
  // chart(tail).
  const auto tailInTail = [&](int h) { return forward(h) ? chart(h).pa : chart(h).motion.inverse()(chart(h).pb); };
  const auto tipInTail = [&](int h) { return forward(h) ? chart(h).pb : chart(h).motion.inverse()(chart(h).pa); };
  const auto tailInTip = [&](int h) { return forward(h) ? chart(h).motion.inverse()(chart(h).pa) : chart(h).pb; };
  const auto motionOf = [&](int h) { return forward(h) ? chart(h).motion : chart(h).motion.inverse(); };
  const auto usable = [&](int h) { return chart(h).ok && m.tail(h) != m.tip(h); };
  // Twice the signed area of p, q, r, and whether it is negative beyond round-off of the sides' product.
  const auto inverted = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    const Eigen::Vector2d u = q - p, v = r - p;
    return u.x() * v.y() - u.y() * v.x() < -1e-12 * u.norm() * v.norm();
  };
  const auto faceInverted = [&](int f) {
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k, g = HalfedgeMesh::prev(h);
      if (m.tail(h) < n0_ || !usable(h) || !usable(g)) continue;
      return inverted(tailInTail(h), tipInTail(h), tailInTip(g));
    }
    return false;
  };
  const auto tryFlip = [&](int e) {
    const int ha = m.edgeHalfedge(e), hb = m.twin(ha);
    if (hb == kInvalid) return false;
    const int na = HalfedgeMesh::next(ha), pa = HalfedgeMesh::prev(ha), nb = HalfedgeMesh::next(hb),
              pb = HalfedgeMesh::prev(hb);
    for (int h : {ha, na, pa, hb, nb, pb})
      if (!usable(h)) return false;
    const int a = m.tail(ha), b = m.tail(hb), c = m.tail(pa), d = m.tail(pb);
    if (c == d) return false;
    // The quad a, d, b, c in the chart of an inserted end u of e; toC, toD: chart(c), chart(d) → chart(u).
    Eigen::Vector2d A, B, C, D;
    PlaneMotion toC, toD;
    if (a >= n0_) {
      A = tailInTail(ha), B = tipInTail(ha), C = tailInTip(pa), D = tipInTail(nb);
      toC = motionOf(pa).inverse(), toD = motionOf(nb);
    } else if (b >= n0_) {
      B = tailInTail(hb), A = tipInTail(hb), D = tailInTip(pb), C = tipInTail(na);
      toC = motionOf(na), toD = motionOf(pb).inverse();
    } else {
      return false;
    }
    // After the flip (HalfedgeMesh::flip): (d, c, a) and (c, d, b), both positive beyond round-off.
    if (!inverted(C, D, A) || !inverted(D, C, B)) return false;
    if (!m.flip(e)) return false;
    const PlaneMotion fromU = toD.inverse();
    EdgeChart& n = charts_[e];
    n.tail = d;
    n.motion = fromU * toC;
    n.pa = fromU(D);
    n.pb = fromU(C);
    n.ok = true;
    out.mesh.edgeLengths[e] = out.pathLength[e] = (C - D).norm();
    return true;
  };
  int flips = 0;
  for (int pass = 0; pass < 8; ++pass) {
    const int before = flips;
    for (int f = 0; f < m.nFaces(); ++f) {
      if (!faceInverted(f)) continue;
      for (int k = 0; k < 3; ++k)
        if (tryFlip(m.edge(3 * f + k))) {
          ++flips;
          break;
        }
    }
    if (flips == before) break;
  }
  return flips;
}

EdgeInFace signpostEdgeInFace(const IntrinsicTriangulation& input, const RefineResult& refined) {
  constexpr double kTolerance = 1e-9;  // rad: see pull_back.h
  const int n0 = input.mesh.nVertices();
  auto frame = std::make_shared<Signposts>(initialSignposts(input));
  return [&input, &refined, frame, n0](int e, int f) {
    const HalfedgeMesh& m1 = refined.triangulation.mesh;
    const int h = m1.edgeHalfedge(e);
    for (int g : {h, m1.twin(h)}) {
      if (g == kInvalid || m1.tail(g) >= n0) continue;
      const int v = m1.tail(g);
      bool inWedge = false;
      for (int k = 0; k < 3 && !inWedge; ++k) {
        const int c = 3 * f + k;
        if (input.mesh.tail(c) != v) continue;
        const double d = frame->reduce(v, refined.signposts.angle[g] - frame->angle[c]);
        inWedge = d <= cornerAngle(input, c) + kTolerance || d >= frame->period[v] - kTolerance;
      }
      if (!inWedge) return false;
    }
    return true;
  };
}

namespace {

bool triangleInFace(const HalfedgeMesh& m1, int f, int face, const EdgeInFace& inFace) {
  if (!inFace) return true;
  for (int k = 0; k < 3; ++k)
    if (!inFace(m1.edge(3 * f + k), face)) return false;
  return true;
}

}  // namespace

// Orientation of the output triangles on T0 where the three vertices can be written in one input face (directly, or
// a vertex or a point on a side re-expressed in a neighbouring face), and the same-face length check: an edge whose
// ends can be written in one face is compared with the straight distance of the ends there. A loop edge (both ends one
// vertex: a geodesic loop around a cone vertex of angle below π, which an intrinsic Delaunay triangulation may hold)
// and its triangles have no such picture in one face; they are counted, not checked.
void checkAgainstLocations(const IntrinsicTriangulation& t0, const IntrinsicTriangulation& t1,
                           const std::vector<Point>& vertexImage, MeshRemeshResult& out, const EdgeInFace& inFace) {
  const HalfedgeMesh &m0 = t0.mesh, &m1 = t1.mesh;
  for (int f = 0; f < m1.nFaces(); ++f) {
    const int v0 = m1.faceVertex(f, 0), v1 = m1.faceVertex(f, 1), v2 = m1.faceVertex(f, 2);
    if (v0 == v1 || v1 == v2 || v2 == v0) continue;
    const Point* p[3] = {&vertexImage[v0], &vertexImage[v1], &vertexImage[v2]};
    for (int k = 0; k < 3; ++k) {
      const int face = p[k]->face;
      Eigen::Vector3d b[3];
      if (!expressIn(m0, *p[0], face, b[0]) || !expressIn(m0, *p[1], face, b[1]) || !expressIn(m0, *p[2], face, b[2]))
        continue;
      if (!triangleInFace(m1, f, face, inFace)) continue;
      Eigen::Matrix3d B;
      B << b[0], b[1], b[2];
      ++out.orientationChecked;
      if (!(B.determinant() > 0) && out.invertedTriangles++ == 0) out.firstInvertedTriangle = {f, face};
      break;
    }
  }
  for (int e = 0; e < m1.nEdges(); ++e) {
    const int h = m1.edgeHalfedge(e);
    if (m1.tail(h) == m1.tip(h)) {
      ++out.loopEdges;
      continue;
    }
    const Point &a = vertexImage[m1.tail(h)], &b = vertexImage[m1.tip(h)];
    Eigen::Vector3d x;
    double d;
    int face;
    if (expressIn(m0, a, b.face, x) && (!inFace || inFace(e, b.face))) {
      d = flatDistance(t0, b.face, x, b.bary);
      face = b.face;
    } else if (expressIn(m0, b, a.face, x) && (!inFace || inFace(e, a.face))) {
      d = flatDistance(t0, a.face, a.bary, x);
      face = a.face;
    } else {
      continue;
    }
    ++out.sameFaceEdges;
    const double error = std::abs(t1.edgeLengths[e] - d) / t1.edgeLengths[e];
    out.maxSameFaceLengthError = std::max(out.maxSameFaceLengthError, error);
    const double side = std::max({t0.length(3 * face), t0.length(3 * face + 1), t0.length(3 * face + 2)});
    const double scaled = std::abs(t1.edgeLengths[e] - d) / std::max(t1.edgeLengths[e], side);
    if (scaled > out.maxSameFaceScaledError) {
      out.maxSameFaceScaledError = scaled;
      out.worstSameFaceEdge = {e, face};
    }
  }
}

// The input route (mesh_remesh.h, top): Delaunay refinement of the input in its own metric. The refiner flips the
// input to its intrinsic Delaunay triangulation first and records every inserted vertex on the input's own faces, so

}  // namespace conformesh::refine::detail
