// discrete_conformal.cpp — vertex-scaled metrics in Penner coordinates and Lawson flipping with Ptolemy lengths
// (Gu–Luo–Sun–Wu 2018). See discrete_conformal.h and docs/ricci_flow.md.
#include "conformesh/intrinsic/flow/discrete_conformal.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic {

double lengthFromPenner(Background g, double c) {
  switch (g) {
    case Background::Euclidean:
      return c;
    case Background::Hyperbolic:
      return 2.0 * std::asinh(0.5 * c);
    case Background::Spherical:
      return 2.0 * std::asin(std::min(1.0, 0.5 * c));
  }
  return c;
}

double pennerFromLength(Background g, double length) {
  switch (g) {
    case Background::Euclidean:
      return length;
    case Background::Hyperbolic:
      return 2.0 * std::sinh(0.5 * length);
    case Background::Spherical:
      return 2.0 * std::sin(0.5 * length);
  }
  return length;
}

double lengthDerivativeInU(Background g, double length) {
  switch (g) {
    case Background::Euclidean:
      return 0.5 * length;
    case Background::Hyperbolic:
      return std::tanh(0.5 * length);
    case Background::Spherical:
      return std::tan(0.5 * length);
  }
  return 0.5 * length;
}

double pennerDelaunayMargin(double ab, double bc, double ca, double ad, double db) {
  // (x² + y² − z²)/(xy) written as x/y + y/x − (z/x)(z/y) to avoid overflow of the squares.
  auto term = [](double x, double y, double z) { return x / y + y / x - (z / x) * (z / y); };
  return term(bc, ca, ab) + term(ad, db, ab);
}

DiscreteConformalMetric::DiscreteConformalMetric(IntrinsicTriangulation reference, Background geometry)
    : tri_(std::move(reference)), geometry_(geometry), u_(tri_.mesh.nVertices(), 0.0) {
  tri_.background = Background::Euclidean;
}

double DiscreteConformalMetric::penner(int e) const {
  const int h = tri_.mesh.edgeHalfedge(e);
  return tri_.edgeLengths[e] * std::exp(0.5 * (u_[tri_.mesh.tail(h)] + u_[tri_.mesh.tip(h)]));
}

std::int64_t DiscreteConformalMetric::makeDelaunay(double tolerance, FlowCorrespondence* log) {
  HalfedgeMesh& m = tri_.mesh;
  const int nE = m.nEdges();
  auto flippable = [&](int e) {
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    if (t == kInvalid) return false;
    const int fa = HalfedgeMesh::face(h), fb = HalfedgeMesh::face(t);
    return fa != fb && !isFrozen(fa) && !isFrozen(fb);
  };
  // Margin at the current u from reference lengths: the scale factors cancel in each of the two ratios except through
  // the vertex weights, so apply them explicitly.
  // u does not change while flipping: one exponential per vertex, c_ij = c⁰_ij e^{u_i/2} e^{u_j/2}.
  std::vector<double> half(u_.size());
  onTwoCores(static_cast<std::ptrdiff_t>(u_.size()), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto v = begin; v < end; ++v) half[v] = std::exp(0.5 * u_[v]);
  });
  auto current = [&](int h) { return tri_.edgeLengths[m.edge(h)] * half[m.tail(h)] * half[m.tip(h)]; };
  auto margin = [&](int e) {
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    return pennerDelaunayMargin(current(h), current(HalfedgeMesh::next(h)), current(HalfedgeMesh::prev(h)),
                                current(HalfedgeMesh::next(t)), current(HalfedgeMesh::prev(t)));
  };
  // Lawson's stack: every flippable edge in increasing order, below the edges that flips push (the quad's four sides
  // when not already waiting). Every edge of the initial sweep is tested when it is reached, with its margin at that
  // time; that margin is the one of the start unless a flip has changed one of its two faces since (it was a side or
  // the diagonal of a flipped quad). The start margins of all edges are computed first on two threads, so most tests
  // are look-ups, and the flips and their order are those of testing every edge when it is reached.
  std::vector<char> flippableAtStart(nE), touched(nE, 0), queued(nE, 0);
  std::vector<double> startMargin(nE);
  onTwoCores(nE, kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
    for (auto e = static_cast<int>(begin); e < end; ++e) {
      flippableAtStart[e] = flippable(e);
      if (flippableAtStart[e]) startMargin[e] = margin(e);
    }
  });
  for (int e = 0; e < nE; ++e) queued[e] = flippableAtStart[e];
  std::vector<int> stack;
  const std::int64_t cap = 1000 * static_cast<std::int64_t>(std::max(1, nE));
  std::int64_t flips = 0;
  int sweep = 0;  // next edge of the initial sweep
  while (true) {
    int e;
    bool fromSweep = false;
    if (!stack.empty()) {
      e = stack.back();
      stack.pop_back();
    } else {
      while (sweep < nE && !flippableAtStart[sweep]) ++sweep;
      if (sweep == nE) break;
      e = sweep++;
      fromSweep = true;
    }
    queued[e] = 0;
    const double value = fromSweep && !touched[e] ? startMargin[e] : margin(e);
    if (!(value < -tolerance)) continue;
    if (!flipPtolemy(e, log)) continue;
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    const int eBc = m.edge(HalfedgeMesh::next(h)), eCa = m.edge(HalfedgeMesh::prev(h));
    const int eAd = m.edge(HalfedgeMesh::next(t)), eDb = m.edge(HalfedgeMesh::prev(t));
    if (++flips > cap)
      throw ConvergenceError("Ptolemy flipping exceeded " + std::to_string(cap) +
                             " flips; the conformal factor is probably not finite");
    touched[e] = 1;
    for (int g : {eBc, eCa, eAd, eDb}) {
      touched[g] = 1;
      if (!queued[g] && flippable(g)) {
        queued[g] = 1;
        stack.push_back(g);
      }
    }
  }
  return flips;
}

bool DiscreteConformalMetric::flipPtolemy(int e, FlowCorrespondence* log) {
  HalfedgeMesh& m = tri_.mesh;
  const int ha = m.edgeHalfedge(e), hb = m.twin(ha);
  if (hb == kInvalid || HalfedgeMesh::face(ha) == HalfedgeMesh::face(hb)) return false;
  PtolemyFlip rec;
  rec.faceA = HalfedgeMesh::face(ha);
  rec.faceB = HalfedgeMesh::face(hb);
  rec.cornerA = static_cast<std::uint8_t>(ha % 3);
  rec.cornerB = static_cast<std::uint8_t>(hb % 3);
  rec.ab = tri_.edgeLengths[e];
  rec.bc = tri_.edgeLengths[m.edge(HalfedgeMesh::next(ha))];
  rec.ca = tri_.edgeLengths[m.edge(HalfedgeMesh::prev(ha))];
  rec.ad = tri_.edgeLengths[m.edge(HalfedgeMesh::next(hb))];
  rec.db = tri_.edgeLengths[m.edge(HalfedgeMesh::prev(hb))];
  // Ptolemy in reference coordinates: the vertex weights of both sides agree (each product carries all four).
  rec.cd = (rec.ad * rec.bc + rec.db * rec.ca) / rec.ab;
  if (!std::isfinite(rec.cd) || !(rec.cd > 0))
    throw ConvergenceError("Ptolemy flip of edge " + std::to_string(e) + " produced length " + std::to_string(rec.cd) +
                           "; the conformal factor is no longer finite");
  if (!m.flip(e)) return false;
  tri_.edgeLengths[e] = rec.cd;
  if (log) log->recordFlip(rec);
  return true;
}

IntrinsicTriangulation DiscreteConformalMetric::triangulation() const {
  IntrinsicTriangulation out;
  out.mesh = tri_.mesh;
  out.background = geometry_;
  out.edgeLengths.resize(tri_.mesh.nEdges());
  for (int e = 0; e < tri_.mesh.nEdges(); ++e) out.edgeLengths[e] = length(e);
  return out;
}

bool DiscreteConformalMetric::allFacesValid() const {
  for (int f = 0; f < tri_.mesh.nFaces(); ++f) {
    if (isFrozen(f)) continue;
    if (!isValidTriangle(geometry_, length(tri_.mesh.edge(3 * f)), length(tri_.mesh.edge(3 * f + 1)),
                         length(tri_.mesh.edge(3 * f + 2))))
      return false;
  }
  return true;
}

}  // namespace conformesh::intrinsic
