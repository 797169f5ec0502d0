// inscribed_disk.cpp — the development of a triangulated polygon onto its circle (inscribed_disk.h), by cross-ratios
// in Boost.Multiprecision's 113-bit cpp_bin_float_quad (header-only); only the factors u are rounded to double.
#include "flow/inscribed_disk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::intrinsic::detail {

namespace {

using Quad = boost::multiprecision::cpp_bin_float_quad;

// Breadth-first face distances from `from` across interior edges; the last face reached is returned in `farthest`.
std::vector<int> dualDistancesFrom(const HalfedgeMesh& m, int from, int& farthest) {
  std::vector<int> dist(m.nFaces(), -1), queue{from};
  dist[from] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int twin = m.twin(HalfedgeMesh::halfedge(queue[i], k));
      if (twin == kInvalid || dist[HalfedgeMesh::face(twin)] >= 0) continue;
      dist[HalfedgeMesh::face(twin)] = dist[queue[i]] + 1;
      queue.push_back(HalfedgeMesh::face(twin));
    }
  farthest = queue.back();
  return dist;
}

// The middle face of a longest path of the dual tree: developed from it, a strip's two crowded ends share the circle
// evenly (a Möbius map that spreads one end crowds the other, and the ends' chords set what double resolves).
int dualTreeCentre(const HalfedgeMesh& m) {
  int p = 0, q = 0;
  dualDistancesFrom(m, 0, p);
  const std::vector<int> fromP = dualDistancesFrom(m, p, q);
  int ignored = 0;
  const std::vector<int> fromQ = dualDistancesFrom(m, q, ignored);
  for (int f = 0; f < m.nFaces(); ++f)
    if (fromP[f] + fromQ[f] == fromP[q] && 2 * fromP[f] >= fromP[q] && 2 * fromP[f] <= fromP[q] + 1) return f;
  return 0;
}

// The Euclidean angle opposite side a by the half-angle formula with Kahan's ordering (sides sorted, differences
// formed before halving), accurate also near 0 and π. Requires a valid triangle. (triangle_geometry.h's angleOpposite
// in Quad: the root face's corners placed to double's accuracy instead tip one of boeing.off's strips at the round-off
// floor from through to refused.)
Quad angleOppositeQuad(const Quad& a, const Quad& b, const Quad& c) {
  const Quad* side[3] = {&a, &b, &c};
  int idx[3] = {0, 1, 2};
  auto order = [&](int i, int j) {
    if (*side[idx[i]] < *side[idx[j]]) std::swap(idx[i], idx[j]);
  };
  order(0, 1);
  order(1, 2);
  order(0, 1);
  const Quad &x = *side[idx[0]], &y = *side[idx[1]], &z = *side[idx[2]];
  Quad diff[3];
  diff[idx[0]] = (z - (x - y)) / 2;
  diff[idx[1]] = (z + (x - y)) / 2;
  diff[idx[2]] = (x + (y - z)) / 2;
  const Quad s = (x + (y + z)) / 2;
  return 2 * boost::multiprecision::atan(boost::multiprecision::sqrt(diff[1] * diff[2] / (s * diff[0])));
}

// u of every vertex of the development from `root` (docs/ricci_flow.md §3.3, "Disks without interior vertices"), in
// Quad. The vertices are placed on the real line, the boundary of the upper half-plane (Möbius-equivalent to the
// circle), by cross-ratios: across an interior edge ab of a placed face (a, b, c) the new vertex d satisfies
//   (x_a − x_c)(x_b − x_d) / ((x_a − x_d)(x_b − x_c)) = −ℓ_ac ℓ_bd / (ℓ_ad ℓ_bc),
// the length cross-ratio of the reference lengths (vertex scaling leaves it unchanged), negative because ab
// separates c from d; solved, x_d = (p x_b + r q x_a)/(p + r q) with p = x_a − x_c, q = x_b − x_c, r the ratio. Each
// x_d is a Möbius function of its face's three points, so round-off is added per face, not multiplied: a cluster of
// chords δ keeps its relative shape to ~ε/δ. (The earlier recursion in u through the angles of the placed faces
// multiplied its error by ~1/δ² per face near the crowded ends of a strip, where those faces' angles approach π:
// ALSTOM_TEST4.off's 36-vertex strip came out 0.8 % outside the triangle inequality in double and 89 % in quadruple
// precision.) Then e^{v_d} = |x_d − x_a||x_d − x_b| ℓ⁰_ab / (|x_a − x_b| ℓ⁰_ad ℓ⁰_bd) is d's factor on the line, and
// the Cayley map onto the unit circle, |z_i − z_j| = 2|x_i − x_j| / √((1 + x_i²)(1 + x_j²)), adds log 2 − log(1 +
// x_d²).
std::vector<Quad> developOntoCircle(const HalfedgeMesh& m, const std::vector<double>& reference, int root) {
  std::vector<Quad> x(m.nVertices(), Quad(0));
  std::vector<Quad> u(m.nVertices(), Quad(0));
  auto ref = [&](int h) { return Quad(reference[m.edge(h)]); };
  // d's factor from its face: halfedges hab (a → b) and the two sides at d, with the reference lengths.
  auto factorOf = [&](int d, int a, int b, const Quad& lab, const Quad& lad, const Quad& lbd) {
    using boost::multiprecision::abs;
    using boost::multiprecision::log;
    const Quad line = log(abs(x[d] - x[a]) * abs(x[d] - x[b]) * lab / (abs(x[a] - x[b]) * lad * lbd));
    u[d] = line + log(Quad(2)) - log(1 + x[d] * x[d]);
  };
  std::vector<char> placed(m.nVertices(), 0), visited(m.nFaces(), 0);
  // The root face keeps its own shape: its corners go where its circumcircle puts them (the arc between two corners
  // twice the angle at the third), so that a disk already inscribed comes out as itself, scaled (λ = log R). On the
  // line, x = −cot(φ/2) for z = e^{iφ}: corner 0 at φ = π (x = 0), corner 1 at π − 2γ₂ (x = −tan γ₂), corner 2 at
  // −π + 2γ₁ (x = tan γ₁).
  const int hs[3] = {HalfedgeMesh::halfedge(root, 0), HalfedgeMesh::halfedge(root, 1),
                     HalfedgeMesh::halfedge(root, 2)};  // corner k → k + 1, opposite corner k + 2
  int corner[3];
  for (int k = 0; k < 3; ++k) corner[k] = m.faceVertex(root, k);
  const Quad gamma1 = angleOppositeQuad(ref(hs[2]), ref(hs[0]), ref(hs[1]));  // corner 1, opposite side 2 → 0
  const Quad gamma2 = angleOppositeQuad(ref(hs[0]), ref(hs[1]), ref(hs[2]));  // corner 2, opposite side 0 → 1
  x[corner[0]] = Quad(0);
  x[corner[1]] = -boost::multiprecision::tan(gamma2);
  x[corner[2]] = boost::multiprecision::tan(gamma1);
  for (int k = 0; k < 3; ++k) placed[corner[k]] = 1;
  for (int k = 0; k < 3; ++k) {
    // Corner k between its sides hs[k − 1] (into k) and hs[k] (out of k), opposite hs[k + 1].
    factorOf(corner[k], corner[(k + 1) % 3], corner[(k + 2) % 3], ref(hs[(k + 1) % 3]), ref(hs[k]),
             ref(hs[(k + 2) % 3]));
  }
  std::vector<int> queue{root};
  visited[root] = 1;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const int f = queue[next];
    for (int k = 0; k < 3; ++k) {
      const int hab = HalfedgeMesh::halfedge(f, k), twin = m.twin(hab);
      if (twin == kInvalid || visited[HalfedgeMesh::face(twin)]) continue;
      const int a = m.tail(hab), b = m.tip(hab);
      const int hbc = HalfedgeMesh::next(hab), hca = HalfedgeMesh::next(hbc);
      // In the new face (b, a, d): halfedges twin = ba, then ad, then db.
      const int had = HalfedgeMesh::next(twin), hdb = HalfedgeMesh::next(had);
      const int c = m.tip(hbc), d = m.tip(had);
      if (placed[d])
        throw ConvergenceError("uniformize: disk without interior vertices: vertex " + std::to_string(d) +
                               " is reached twice, the faces do not form a triangulated polygon");
      const Quad r = ref(hca) * ref(hdb) / (ref(had) * ref(hbc));
      const Quad p = x[a] - x[c], q = x[b] - x[c];
      x[d] = (p * x[b] + r * q * x[a]) / (p + r * q);
      factorOf(d, a, b, ref(hab), ref(had), ref(hdb));
      placed[d] = 1;
      visited[HalfedgeMesh::face(twin)] = 1;
      queue.push_back(HalfedgeMesh::face(twin));
    }
  }
  return u;
}

// The shortest edge of the development over its circle's diameter (the unit circle: diameter 2); non-finite lengths
// are skipped.
double shortestChord(const std::vector<double>& lengths) {
  double shortest = std::numeric_limits<double>::infinity();
  for (double l : lengths) shortest = std::min(shortest, l / 2);
  return shortest;
}

// Whether every face satisfies the triangle inequality with these lengths (per edge) in double.
bool allFacesValidIn(const HalfedgeMesh& m, const std::vector<double>& lengths) {
  for (int f = 0; f < m.nFaces(); ++f)
    if (!isValidTriangle(Background::Euclidean, lengths[m.edge(HalfedgeMesh::halfedge(f, 0))],
                         lengths[m.edge(HalfedgeMesh::halfedge(f, 1))], lengths[m.edge(HalfedgeMesh::halfedge(f, 2))]))
      return false;
  return true;
}

// The faces of `m` whose three corners all lie on the boundary, grouped into parts joined across interior edges;
// each part as its face list.
std::vector<std::vector<int>> allBoundaryParts(const HalfedgeMesh& m) {
  std::vector<char> allBoundary(m.nFaces(), 0);
  for (int f = 0; f < m.nFaces(); ++f)
    allBoundary[f] = m.isBoundaryVertex(m.faceVertex(f, 0)) && m.isBoundaryVertex(m.faceVertex(f, 1)) &&
                     m.isBoundaryVertex(m.faceVertex(f, 2));
  std::vector<char> seen(m.nFaces(), 0);
  std::vector<std::vector<int>> parts;
  for (int start = 0; start < m.nFaces(); ++start) {
    if (!allBoundary[start] || seen[start]) continue;
    std::vector<int> part{start};
    seen[start] = 1;
    for (std::size_t i = 0; i < part.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int twin = m.twin(HalfedgeMesh::halfedge(part[i], k));
        if (twin == kInvalid || !allBoundary[HalfedgeMesh::face(twin)] || seen[HalfedgeMesh::face(twin)]) continue;
        seen[HalfedgeMesh::face(twin)] = 1;
        part.push_back(HalfedgeMesh::face(twin));
      }
    parts.push_back(std::move(part));
  }
  return parts;
}

// The faces `part` of `reference` as a triangulation of their own (vertices renumbered, edge ids kept so that
// multi-edges stay apart); null when they do not form a disk (Euler characteristic 1, one boundary loop), which a
// part can fail to be where it touches itself at a vertex.
std::unique_ptr<DiscreteConformalMetric> partAsDisk(const IntrinsicTriangulation& reference,
                                                    const std::vector<int>& part) {
  const HalfedgeMesh& m = reference.mesh;
  std::vector<int> vertex(m.nVertices(), -1), edge(m.nEdges(), -1);
  std::vector<std::array<int, 3>> faces, edgeIds;
  int nV = 0, nE = 0;
  for (int f : part) {
    std::array<int, 3> face{}, ids{};
    for (int k = 0; k < 3; ++k) {
      const int v = m.faceVertex(f, k), e = m.edge(HalfedgeMesh::halfedge(f, k));
      if (vertex[v] < 0) vertex[v] = nV++;
      if (edge[e] < 0) edge[e] = nE++;
      face[k] = vertex[v];
      ids[k] = edge[e];
    }
    faces.push_back(face);
    edgeIds.push_back(ids);
  }
  IntrinsicTriangulation sub;
  sub.mesh = HalfedgeMesh::fromFaces(faces, nV, "", nullptr, edgeIds);
  if (sub.mesh.nFaces() != static_cast<int>(part.size()) || nV - sub.mesh.nEdges() + sub.mesh.nFaces() != 1)
    return nullptr;
  int boundaryHalfedges = 0, boundaryVertices = 0;
  for (int h = 0; h < sub.mesh.nHalfedges(); ++h) boundaryHalfedges += sub.mesh.twin(h) == kInvalid;
  for (int v = 0; v < nV; ++v) boundaryVertices += sub.mesh.isBoundaryVertex(v);
  if (boundaryHalfedges != nV || boundaryVertices != nV) return nullptr;
  // A part is a subset of an oriented mesh, so its faces keep their order and corners.
  sub.edgeLengths.resize(sub.mesh.nEdges());
  for (std::size_t j = 0; j < part.size(); ++j)
    for (int k = 0; k < 3; ++k)
      sub.edgeLengths[sub.mesh.edge(HalfedgeMesh::halfedge(static_cast<int>(j), k))] =
          reference.edgeLengths[m.edge(HalfedgeMesh::halfedge(part[j], k))];
  return std::make_unique<DiscreteConformalMetric>(std::move(sub), Background::Euclidean);
}

}  // namespace

std::vector<double> inscribeDiskWithoutInterior(DiscreteConformalMetric& metric) {
  const HalfedgeMesh& m = metric.mesh();
  const std::vector<Quad> u = developOntoCircle(m, metric.referencePennerLengths(), dualTreeCentre(m));
  for (int v = 0; v < m.nVertices(); ++v) metric.u()[v] = static_cast<double>(u[v]);
  std::vector<double> lengths(m.nEdges());
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    lengths[e] = static_cast<double>(boost::multiprecision::exp((u[m.tail(h)] + u[m.tip(h)]) / 2) *
                                     Quad(metric.referencePenner(e)));
  }
  if (allFacesValidIn(m, lengths)) return lengths;
  // A long strip crowds its ends exponentially (a rectangle L × w: chords ~ e^{−πL/2w} of the diameter). Three
  // vertices on a circle at chords δ (in diameters) leave the triangle inequality a relative margin ≈ δ²/2, which
  // lengths rounded to double (relative 1.1·10⁻¹⁶) keep only down to δ ≈ 10⁻⁸: below that the circle domain itself
  // is not representable in double, whatever the development's precision.
  std::ostringstream message;
  message.precision(3);
  message << "uniformize: disk without interior vertices: its circle domain is not representable in double precision "
             "(developed in quadruple precision, a face violates the triangle inequality once its lengths are rounded "
             "to double; shortest finite chord "
          << shortestChord(lengths) << " diameters): a long strip, whose circle domain crowds its ends exponentially";
  throw ConvergenceError(message.str());
}

ConvergenceError explainInscribedFailure(const DiscreteConformalMetric& metric, double tolerance,
                                         const ConvergenceError& failed) {
  const HalfedgeMesh& m = metric.mesh();
  double smallest = M_PI;
  for (int f = 0; f < m.nFaces(); ++f) {
    const double l[3] = {metric.length(m.edge(HalfedgeMesh::halfedge(f, 0))),
                         metric.length(m.edge(HalfedgeMesh::halfedge(f, 1))),
                         metric.length(m.edge(HalfedgeMesh::halfedge(f, 2)))};
    if (!isValidTriangle(Background::Euclidean, l[0], l[1], l[2])) continue;
    for (int k = 0; k < 3; ++k)
      smallest = std::min(smallest, angleOpposite(Background::Euclidean, l[k], l[(k + 1) % 3], l[(k + 2) % 3]));
  }
  const double floor = std::numeric_limits<double>::epsilon() / smallest;
  if (!(floor * 100 >= tolerance)) return failed;
  std::ostringstream message;
  message.precision(3);
  message
      << failed.what() << "; this disk has no interior vertex and was developed onto its circle in quadruple "
      << "precision, but its smallest angle there, " << smallest << " rad, puts double's round-off in the angle "
      << "sums at ≈ " << floor << " rad, within 100× of the tolerance " << tolerance
      << ": a long strip, whose circle domain crowds its ends exponentially, not resolved to the tolerance in double "
         "precision";
  return ConvergenceError(message.str());
}

std::string unrepresentableBoundaryPart(const IntrinsicTriangulation& reference) {
  for (const std::vector<int>& part : allBoundaryParts(reference.mesh)) {
    if (part.size() < 2) continue;
    std::unique_ptr<DiscreteConformalMetric> disk = partAsDisk(reference, part);
    if (!disk) continue;
    try {
      inscribeDiskWithoutInterior(*disk);
    } catch (const ConvergenceError& failed) {
      std::ostringstream message;
      message << "the " << part.size() << " faces with every corner on the boundary around face " << part.front()
              << " (" << disk->nVertices() << " vertices) form a disk without interior vertices, whose circle domain "
              << "is a Möbius image of that part of this disk's: " << failed.what();
      return message.str();
    }
  }
  return {};
}

}  // namespace conformesh::intrinsic::detail
