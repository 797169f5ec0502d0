// gaussian_curvature_measure.cpp — per-vertex discrete and smooth Gaussian curvature measures over graph-geodesic balls
// (paper eqs. 1 and 5), with the smooth side integrated triangle by triangle on the chart's reference surface, and on a
// surface with boundary the boundary atoms: ∫k_g ds along the images of the boundary edges and the turning π − α at
// the boundary vertices (smooth), π − Σθ at the boundary vertices (discrete).
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include <Eigen/LU>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/metric/reference_surface.h"
#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic {

namespace {

// The 7-point degree-5 rule on the triangle (Radon 1948; Strang–Fix): nodes as (s, t) in the unit triangle
// {s, t ≥ 0, s + t ≤ 1} (barycentric (1 − s − t, s, t)), weights summing to 1.
constexpr double kA1 = 0.059715871789769820, kB1 = 0.470142064105115090, kW1 = 0.132394152788506181;
constexpr double kA2 = 0.797426985353087322, kB2 = 0.101286507323456339, kW2 = 0.125939180544827153;
constexpr double kNodes[7][2] = {{1.0 / 3, 1.0 / 3}, {kB1, kB1}, {kA1, kB1}, {kB1, kA1},
                                 {kB2, kB2},         {kA2, kB2}, {kB2, kA2}};
constexpr double kWeights[7] = {0.225, kW1, kW1, kW1, kW2, kW2, kW2};

// The pulled-back curvature density ρ(s, t) = K √det g |∂(u,v)/∂(s,t)| of one mesh triangle, sampled at the seven
// nodes. From those samples: ∫K dA and ∫|K| dA over the triangle (the degree-5 rule: error O(h⁶) relative to the
// integral for a triangle of size h, far below the O(ε) errors being measured), and the least-squares quadratic q(s, t)
// through them, which the rim of a ball integrates over cut triangles (midpoint rule, exact for quadratics).
struct FaceDensity {
  double integral = 0, absIntegral = 0;
  double orientation = 1;     // +1 when the face's vertex order is counter-clockwise in the (u, v) chart, else −1
  std::array<double, 6> q{};  // q = q0 + q1 s + q2 t + q3 s² + q4 st + q5 t²

  double at(double s, double t) const {
    return q[0] + q[1] * s + q[2] * t + q[3] * s * s + q[4] * s * t + q[5] * t * t;
  }
  // ∫ q over the (s, t)-triangle p0 p1 p2.
  double over(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) const {
    const Eigen::Vector2d a = p1 - p0, b = p2 - p0;
    const double area = 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    const Eigen::Vector2d m0 = 0.5 * (p0 + p1), m1 = 0.5 * (p1 + p2), m2 = 0.5 * (p2 + p0);
    return area * (at(m0.x(), m0.y()) + at(m1.x(), m1.y()) + at(m2.x(), m2.y())) / 3;
  }
};

// The 6 × 7 least-squares operator from node values to quadratic coefficients, computed once.
const Eigen::Matrix<double, 6, 7>& quadraticFit() {
  static const Eigen::Matrix<double, 6, 7> fit = [] {
    Eigen::Matrix<double, 7, 6> V;
    for (int i = 0; i < 7; ++i) {
      const double s = kNodes[i][0], t = kNodes[i][1];
      V.row(i) << 1, s, t, s * s, s * t, t * t;
    }
    return Eigen::Matrix<double, 6, 7>((V.transpose() * V).inverse() * V.transpose());
  }();
  return fit;
}

FaceDensity sampleFace(const ChartDomain& d, const ChartFunction& density, const Eigen::Vector3d& y0,
                       const Eigen::Vector3d& y1, const Eigen::Vector3d& y2) {
  const Eigen::Vector3d es = y1 - y0, et = y2 - y0;
  Eigen::Matrix<double, 7, 1> values;
  FaceDensity fd;
  for (int i = 0; i < 7; ++i) {
    const Eigen::Vector3d x = y0 + kNodes[i][0] * es + kNodes[i][1] * et;
    Eigen::Vector2d ds, dt;
    chartPoint(d, x, es, &ds);
    chartPoint(d, x, et, &dt);
    const Eigen::Vector2d uv = chartCoordinates(d, x);
    const double jacobian = ds.x() * dt.y() - ds.y() * dt.x();
    if (i == 0) fd.orientation = jacobian < 0 ? -1 : 1;  // at the centroid, away from any pole
    values[i] = density(uv.x(), uv.y()) * std::abs(jacobian);
    fd.integral += 0.5 * kWeights[i] * values[i];  // the unit triangle has area 1/2
    fd.absIntegral += 0.5 * kWeights[i] * std::abs(values[i]);
  }
  const Eigen::Matrix<double, 6, 1> q = quadraticFit() * values;
  for (int k = 0; k < 6; ++k) fd.q[k] = q[k];
  return fd;
}

// === boundary atoms

// 4-point Gauss–Legendre on [0, 1] (exact for degree 7): nodes (1 ± x)/2, weights w/2, x and w the classical ones.
constexpr double kGlX1 = 0.339981043584856265, kGlX2 = 0.861136311594052575;
constexpr double kGlW1 = 0.652145154862546143, kGlW2 = 0.347854845137453857;
constexpr double kGlNodes[4] = {0.5 * (1 - kGlX2), 0.5 * (1 - kGlX1), 0.5 * (1 + kGlX1), 0.5 * (1 + kGlX2)};
constexpr double kGlWeights[4] = {0.5 * kGlW2, 0.5 * kGlW1, 0.5 * kGlW1, 0.5 * kGlW2};

// Position, velocity and acceleration in the chart of the curve that a straight reference segment x(t) = x0 + t·e
// maps to: on planar reference surfaces (rectangle, cylinder, torus) the chart is the reference plane, so c' = e and
// c'' = 0; on the disk's plane the chart is polar, (u, v) = (φ, ρ), and ρ' = p·q/ρ, ρ'' = (|q|² − ρ'²)/ρ,
// φ' = (p × q)/ρ², φ'' = −2 φ' ρ'/ρ for p = x(t), q = e (never at the pole: boundary edges lie on or inside ρ = v1 > 0,
// away from the centre). Sphere charts have no boundary; a mesh with boundary on one is rejected before this is called.
struct CurveJet {
  Eigen::Vector2d uv, d1, d2;
};
CurveJet segmentJet(const ChartDomain& d, const Eigen::Vector3d& x0, const Eigen::Vector3d& e, double t) {
  const Eigen::Vector3d x = x0 + t * e;
  CurveJet c;
  c.uv = chartCoordinates(d, x);
  if (d.shape() == ChartShape::Disk) {
    const Eigen::Vector2d p = x.head<2>(), q = e.head<2>();
    const double rho = p.norm(), drho = p.dot(q) / rho, dphi = (p.x() * q.y() - p.y() * q.x()) / (rho * rho);
    c.d1 = {dphi, drho};
    c.d2 = {-2 * dphi * drho / rho, (q.squaredNorm() - drho * drho) / rho};
  } else {
    c.d1 = e.head<2>();
    c.d2.setZero();
  }
  return c;
}

// √det g · det[c', ∇_{c'}c'] and |c'|²_g at one point: ∇_{c'}c' = c'' + g⁻¹ w with w_l = Γ_{l,ij} c'^i c'^j
// = ((c'^u ∂_u g + c'^v ∂_v g) c')_l − ½ c'ᵀ (∂_l g) c' (Christoffel symbols of the first kind).
struct CurvatureTerms {
  double signedTurn = 0, speed2 = 0;
};
CurvatureTerms curvatureTerms(const MetricJet& j, const Eigen::Vector2d& c1, const Eigen::Vector2d& c2) {
  const Eigen::Matrix2d dg = c1.x() * j.gu + c1.y() * j.gv;
  Eigen::Vector2d w = dg * c1;
  w.x() -= 0.5 * c1.dot(j.gu * c1);
  w.y() -= 0.5 * c1.dot(j.gv * c1);
  const Eigen::Vector2d a = c2 + j.g.inverse() * w;
  return {std::sqrt(j.g.determinant()) * (c1.x() * a.y() - c1.y() * a.x()), c1.dot(j.g * c1)};
}

struct SignedIntegral {
  double value = 0, absValue = 0;
};

// ∫ k_g ds over the parameter interval [t0, t1] of the curve of reference segment x0 + t·e, k_g signed toward the
// side `side` (+1: the chart's left, −1: its right): the integrand k_g |c'|_g = side · √det g det[c', ∇c'] / |c'|²_g.
SignedIntegral segmentCurvature(const SmoothMetric& metric, const ChartDomain& d, const Eigen::Vector3d& x0,
                                const Eigen::Vector3d& e, double side, double t0, double t1) {
  SignedIntegral out;
  for (int i = 0; i < 4; ++i) {
    const CurveJet c = segmentJet(d, x0, e, t0 + (t1 - t0) * kGlNodes[i]);
    const CurvatureTerms k = curvatureTerms(metric.jet(c.uv.x(), c.uv.y()), c.d1, c.d2);
    const double f = side * k.signedTurn / k.speed2;
    out.value += kGlWeights[i] * (t1 - t0) * f;
    out.absValue += kGlWeights[i] * (t1 - t0) * std::abs(f);
  }
  return out;
}

// Everything the regions are measured from: the per-face smooth densities, the discrete atoms, and on a mesh with
// boundary the per-boundary-halfedge ∫k_g ds and per-boundary-vertex smooth turning.
struct MeasureContext {
  const HalfedgeMesh& m;
  const std::vector<Eigen::Vector3d>& ref;
  const SmoothMetric& metric;
  ChartDomain domain;
  bool boundaryTerms;
  std::vector<FaceDensity> face;
  std::vector<double> atom;  // discrete: 2π − Σθ inside, π − Σθ on the boundary (0 there without terms)
  std::vector<SignedIntegral> edgeKg;  // per halfedge; only boundary halfedges are filled
  std::vector<double> turning;         // per vertex: π − α at boundary vertices (smooth), else 0
  std::vector<int> fanStart,
      fanFaces;  // per vertex x: its faces in fan-walk order, fanFaces[fanStart[x], fanStart[x+1])
  double smoothTotal = 0, smoothBoundary = 0;

  MeasureContext(const IntrinsicTriangulation& mesh, const std::vector<Eigen::Vector3d>& referencePoints,
                 const SmoothMetric& sm, bool withBoundary)
      : m(mesh.mesh), ref(referencePoints), metric(sm), domain(sm.domain()), boundaryTerms(withBoundary) {
    if (mesh.background != Background::Euclidean)
      throw InputError(
          "curvature measure: the mesh's lengths must be Euclidean (measured in the original metric), "
          "found " +
          toString(mesh.background));
    if (static_cast<int>(ref.size()) != m.nVertices())
      throw InputError("curvature measure: expected one reference point per vertex (" + std::to_string(m.nVertices()) +
                       "), found " + std::to_string(ref.size()));
    // Smooth side, once per triangle: ∫K dA and ∫|K| dA over the triangle's image, and the quadratic fit of the
    // density for triangles that a ball's rim cuts.
    const ChartFunction kDensity = curvatureDensity(metric);
    sampleFaces(kDensity);
    for (int f = 0; f < m.nFaces(); ++f) smoothTotal += face[f].integral;  // in index order, whatever the threads
    flattenFans();
    atom = vertexCurvatures(mesh);
    turning.assign(m.nVertices(), 0.0);
    edgeKg.assign(m.nHalfedges(), {});
    for (int v = 0; v < m.nVertices(); ++v)
      if (!boundaryTerms && m.isBoundaryVertex(v)) atom[v] = 0;
    if (!boundaryTerms) return;
    const ChartShape shape = domain.shape();
    for (int h = 0; h < m.nHalfedges(); ++h) {
      if (m.twin(h) != kInvalid) continue;
      if (shape == ChartShape::Sphere)
        throw InputError("curvature measure: edge " + std::to_string(m.edge(h)) + " (vertices " +
                         std::to_string(m.tail(h)) + "–" + std::to_string(m.tip(h)) +
                         ") is a boundary edge, but boundary terms are not available on the sphere chart (its "
                         "reference is the gnomonic sphere); expected a closed mesh, or boundaryTerms = false");
      // The face lies to the left of its halfedge in the mesh's orientation, which is the chart's left when the face
      // is counter-clockwise in the chart: k_g is measured toward the interior.
      edgeKg[h] =
          segmentCurvature(metric, domain, ref[m.tail(h)], segment(h), face[HalfedgeMesh::face(h)].orientation, 0, 1);
      smoothBoundary += edgeKg[h].value;
    }
    for (int v = 0; v < m.nVertices(); ++v) {
      if (!m.isBoundaryVertex(v)) continue;
      turning[v] = vertexTurning(v);
      smoothBoundary += turning[v];
    }
  }

  // face[f] for every face, on two cores (each face is written by one chunk; the metric is read only). An exception
  // in a chunk is rethrown here, the lowest chunk's, as a serial loop would have thrown the first (two_threads.h).
  void sampleFaces(const ChartFunction& kDensity) {
    face.resize(m.nFaces());
    onTwoCores(m.nFaces(), kParallelMin, [&](std::ptrdiff_t f0, std::ptrdiff_t f1) {
      for (int f = static_cast<int>(f0); f < f1; ++f) {
        const Eigen::Vector3d& a = ref[m.faceVertex(f, 0)];
        face[f] = sampleFace(domain, kDensity, a, unwrapNear(domain, a, ref[m.faceVertex(f, 1)]),
                             unwrapNear(domain, a, ref[m.faceVertex(f, 2)]));
      }
    });
  }

  // The faces around every vertex in the order the halfedge fan walk (vertexHalfedge, nextOutgoing) visits them.
  void flattenFans() {
    fanStart.assign(m.nVertices() + 1, 0);
    fanFaces.reserve(m.nFaces() * 3);
    for (int x = 0; x < m.nVertices(); ++x) {
      const int start = m.vertexHalfedge(x);
      int h = start;
      do {
        fanFaces.push_back(HalfedgeMesh::face(h));
        h = m.nextOutgoing(h);
      } while (h != kInvalid && h != start);
      fanStart[x + 1] = static_cast<int>(fanFaces.size());
    }
  }

  // Reference vector of halfedge h, tail to tip, unwrapped across periodic seams.
  Eigen::Vector3d segment(int h) const {
    const Eigen::Vector3d& x0 = ref[m.tail(h)];
    return unwrapNear(domain, x0, ref[m.tip(h)]) - x0;
  }

  // π − α at boundary vertex v, α ∈ (0, 2π) the metric angle of η(T) there: from the outgoing boundary curve's tangent
  // b counter-clockwise (in the mesh's orientation, through the interior) to the reversed incoming tangent a.
  double vertexTurning(int v) const {
    const int hOut = m.vertexHalfedge(v);
    int h = hOut;
    for (int n = m.nextOutgoing(h); n != kInvalid; n = m.nextOutgoing(n)) h = n;
    const int hIn = HalfedgeMesh::prev(h);  // the incoming boundary halfedge closes the fan
    const Eigen::Vector3d& xv = ref[v];
    const Eigen::Vector2d b = segmentJet(domain, xv, segment(hOut), 0).d1;
    const Eigen::Vector3d xt = unwrapNear(domain, xv, ref[m.tail(hIn)]);
    const Eigen::Vector2d a = -segmentJet(domain, xt, xv - xt, 1).d1;
    const Eigen::Vector2d uv = chartCoordinates(domain, xv);
    const Eigen::Matrix2d g = metric.g(uv.x(), uv.y());
    const double side = face[HalfedgeMesh::face(hOut)].orientation;
    double alpha = std::atan2(side * std::sqrt(g.determinant()) * (b.x() * a.y() - b.y() * a.x()), b.dot(g * a));
    if (alpha < 0) alpha += 2 * M_PI;
    return M_PI - alpha;
  }

  // The two measures and the scale of {d < r} (GeodesicBall semantics) over the candidate vertices `reached` (which
  // must hold every vertex within r and all their neighbours), d read through distanceOf; `stamp` marks visited faces.
  template <class Distance>
  RegionCurvatureMeasure sublevelSet(const std::vector<int>& reached, const Distance& distanceOf, double r, int stamp,
                                     std::vector<int>& faceStamp) const {
    RegionCurvatureMeasure out;
    for (int x : reached) {
      if (distanceOf(x) >= r) continue;
      out.discrete += atom[x];
      if (boundaryTerms && m.isBoundaryVertex(x)) addBoundaryAtoms(x, distanceOf, r, out);
    }
    for (int x : reached) {
      if (distanceOf(x) >= r) continue;
      for (int fk = fanStart[x]; fk < fanStart[x + 1]; ++fk) {
        const int f = fanFaces[fk];
        if (faceStamp[f] == stamp) continue;
        faceStamp[f] = stamp;
        const double d[3] = {distanceOf(m.faceVertex(f, 0)), distanceOf(m.faceVertex(f, 1)),
                             distanceOf(m.faceVertex(f, 2))};
        addFace(f, d, r, out);
      }
    }
    return out;
  }

  // The smooth atoms of boundary vertex x (inside {d < r}): its turning, and the parts inside of the boundary edges
  // with an end at x — the outgoing one always, the incoming one when its tail is outside (else it is counted from
  // there). The part inside is where the linearly interpolated d is below r, cut at the same parameter as the triangle
  // it bounds.
  template <class Distance>
  void addBoundaryAtoms(int x, const Distance& distanceOf, double r, RegionCurvatureMeasure& out) const {
    out.smooth += turning[x];
    out.absoluteScale += std::abs(turning[x]);
    const int hOut = m.vertexHalfedge(x);
    int h = hOut;
    for (int n = m.nextOutgoing(h); n != kInvalid; n = m.nextOutgoing(n)) h = n;
    const int hIn = HalfedgeMesh::prev(h);
    for (int e : {hOut, hIn}) {
      const double d0 = distanceOf(m.tail(e)), d1 = distanceOf(m.tip(e));
      if (e == hIn && d0 < r) continue;
      SignedIntegral k;
      if (d0 < r && d1 < r) {
        k = edgeKg[e];
      } else {
        const double t = (r - d0) / (d1 - d0);
        const double side = face[HalfedgeMesh::face(e)].orientation;
        k = d0 < r ? segmentCurvature(metric, domain, ref[m.tail(e)], segment(e), side, 0, t)
                   : segmentCurvature(metric, domain, ref[m.tail(e)], segment(e), side, t, 1);
      }
      out.smooth += k.value;
      out.absoluteScale += k.absValue;
    }
  }

  // Face f's share of {d < r}, d[k] the level at its k-th vertex: nothing when no vertex is inside, its whole ∫K dA and
  // ∫|K| dA when all three are, else the part the rim d = r (d interpolated linearly) leaves inside.
  void addFace(int f, const double d[3], double r, RegionCurvatureMeasure& out) const {
    addFaceShare(face[f], d, r, out);
  }
  // Not inlined, so that it is compiled once, for the default target, whichever clone calls it.
  __attribute__((noinline)) static void addFaceShare(const FaceDensity& fd, const double d[3], double r,
                                                     RegionCurvatureMeasure& out) {
    int inside = 0;
    for (int k = 0; k < 3; ++k) inside += d[k] < r;
    if (inside == 0) return;
    if (inside == 3) {
      out.smooth += fd.integral;
      out.absoluteScale += fd.absIntegral;
      return;
    }
    // The rim cuts the triangle: integrate the face's quadratic density over the part inside, one or two
    // sub-triangles in the face's (s, t) = (b1, b2) coordinates.
    const Eigen::Vector2d corner[3] = {{0, 0}, {1, 0}, {0, 1}};
    auto cut = [&](int i, int j, double& t) {  // the rim's crossing of edge i → j, i inside, j outside
      t = (r - d[i]) / (d[j] - d[i]);
      return Eigen::Vector2d((1 - t) * corner[i] + t * corner[j]);
    };
    double fraction = 0, ti = 0, tj = 0;
    if (inside == 1) {
      const int i = d[0] < r ? 0 : (d[1] < r ? 1 : 2), j = (i + 1) % 3, k = (i + 2) % 3;
      const Eigen::Vector2d pj = cut(i, j, ti), pk = cut(i, k, tj);
      out.smooth += fd.over(corner[i], pj, pk);
      fraction = ti * tj;
    } else {
      const int o = d[0] >= r ? 0 : (d[1] >= r ? 1 : 2), i = (o + 1) % 3, j = (o + 2) % 3;
      const Eigen::Vector2d pi = cut(i, o, ti), pj = cut(j, o, tj);
      out.smooth += fd.over(corner[i], corner[j], pj) + fd.over(corner[i], pj, pi);
      fraction = 1 - (1 - ti) * (1 - tj);
    }
    out.absoluteScale += fraction * fd.absIntegral;
  }

  // Theorem 3.4's region: the relative interior (in M) of the union of the triangles whose three vertices are within
  // r — its triangles, the boundary edges of M on them, and the vertices whose whole fan is in it.
  template <class Distance>
  RegionCurvatureMeasure triangleUnion(const std::vector<int>& reached, const Distance& distanceOf, double r, int stamp,
                                       std::vector<int>& faceStamp) const {
    RegionCurvatureMeasure out;
    for (int x : reached) {
      for (int fk = fanStart[x]; fk < fanStart[x + 1]; ++fk) {
        const int f = fanFaces[fk];
        if (faceStamp[f] != stamp && distanceOf(m.faceVertex(f, 0)) < r && distanceOf(m.faceVertex(f, 1)) < r &&
            distanceOf(m.faceVertex(f, 2)) < r) {
          faceStamp[f] = stamp;
          out.smooth += face[f].integral;
          out.absoluteScale += face[f].absIntegral;
          if (boundaryTerms)
            for (int k = 0; k < 3; ++k) {
              const int e = HalfedgeMesh::halfedge(f, k);
              if (m.twin(e) != kInvalid) continue;
              out.smooth += edgeKg[e].value;
              out.absoluteScale += edgeKg[e].absValue;
            }
        }
      }
    }
    for (int x : reached) {
      if (distanceOf(x) >= r || (!boundaryTerms && m.isBoundaryVertex(x))) continue;
      bool inside = true;
      for (int k = fanStart[x]; k < fanStart[x + 1] && inside; ++k) inside = faceStamp[fanFaces[k]] == stamp;
      if (!inside) continue;
      out.discrete += atom[x];
      out.smooth += turning[x];
      out.absoluteScale += std::abs(turning[x]);
    }
    return out;
  }
};

// The neighbours of every vertex in the order the halfedge fan walk relaxes them (the tip of each outgoing halfedge,
// and at a boundary fan's end the tail of the incoming boundary halfedge), with their edge lengths:
// list[start[x], start[x+1]).
struct Neighbours {
  std::vector<int> start;
  std::vector<std::pair<int, double>> list;
};
Neighbours flattenNeighbours(const IntrinsicTriangulation& mesh) {
  const HalfedgeMesh& m = mesh.mesh;
  const int nV = m.nVertices();
  Neighbours n;
  n.start.assign(nV + 1, 0);
  n.list.reserve(m.nHalfedges() + nV);
  for (int x = 0; x < nV; ++x) {
    const int start = m.vertexHalfedge(x);
    int h = start;
    do {
      n.list.push_back({m.tip(h), mesh.length(h)});
      const int hp = HalfedgeMesh::prev(h);
      if (m.twin(hp) == kInvalid) n.list.push_back({m.tail(hp), mesh.length(hp)});
      h = m.nextOutgoing(h);
    } while (h != kInvalid && h != start);
    n.start[x + 1] = static_cast<int>(n.list.size());
  }
  return n;
}

// The balls of gaussianCurvatureMeasure, one per vertex: Dijkstra from the centre over the graph of edges, cut at
// reach = r + the longest edge (so that every triangle the rim cuts has all three distances), then the region's two
// measures. Each ball costs its size, a fixed fraction of the vertices, so all n of them cost O(n²)
// (docs/benchmarks.md); this class keeps the constant small: the neighbours with their edge lengths (and in
// MeasureContext the fans' faces), in the order the halfedge fan walk visits them, are flattened into arrays once, and
// the balls are shared between two cores (runChunks). Every ball's sums run over the same vertices and faces in the
// same order as a serial sweep — the Dijkstra pop order, (distance, vertex) ascending — so the results do not depend on
// the threads.
class BallSweep {
 public:
  BallSweep(const MeasureContext& ctx, const IntrinsicTriangulation& mesh, double radius, MeasureRegion region)
      : ctx_(ctx), m_(mesh.mesh), radius_(radius), region_(region) {
    reach_ = radius + *std::max_element(mesh.edgeLengths.begin(), mesh.edgeLengths.end());
    const Neighbours n = flattenNeighbours(mesh);
    adjStart_ = n.start;
    adj_ = n.list;
  }

  // Fills r.discrete, r.smooth, r.absoluteScale and r.relativeError at the (distinct) vertices `centres`, in blocks
  // of a hundredth of them (progress after each).
  void run(const std::vector<int>& centres, CurvatureMeasureResult& r,
           const std::function<void(int, int)>& progress) const {
    const int n = static_cast<int>(centres.size()), block = (n + 99) / 100;
    for (int b0 = 0; b0 < n; b0 += block) {
      const int b1 = std::min(n, b0 + block);
      constexpr int kChunks = 8;
      runChunks(kChunks, [&](int c) {
        std::unique_ptr<Scratch> s = takeScratch();
        for (int i = b0 + (b1 - b0) * c / kChunks; i < b0 + (b1 - b0) * (c + 1) / kChunks; ++i)
          measureBall(centres[i], *s, r);
        giveScratch(std::move(s));
      });
      if (progress) progress(b1, n);
    }
  }

 private:
  // Per-thread work arrays, reused from ball to ball (stamps are the centre's index, so nothing is cleared).
  struct Scratch {
    std::vector<double> dist;
    std::vector<int> vertexStamp, faceStamp, reached;
    std::vector<std::pair<double, int>> heap;
  };

  std::unique_ptr<Scratch> takeScratch() const {
    std::lock_guard<std::mutex> lock(poolMutex_);
    if (pool_.empty()) {
      auto s = std::make_unique<Scratch>();
      s->dist.assign(m_.nVertices(), INFINITY);
      s->vertexStamp.assign(m_.nVertices(), -1);
      s->faceStamp.assign(m_.nFaces(), -1);
      return s;
    }
    std::unique_ptr<Scratch> s = std::move(pool_.back());
    pool_.pop_back();
    return s;
  }
  void giveScratch(std::unique_ptr<Scratch> s) const {
    std::lock_guard<std::mutex> lock(poolMutex_);
    pool_.push_back(std::move(s));
  }

  // Dijkstra from v up to reach_: s.reached lists the vertices in pop order, s.dist their distances.
  void grow(int v, Scratch& s) const {
    s.reached.clear();
    s.dist[v] = 0;
    const auto later = std::greater<std::pair<double, int>>();
    s.heap.assign(1, {0.0, v});
    while (!s.heap.empty()) {
      std::pop_heap(s.heap.begin(), s.heap.end(), later);
      const auto [dv, x] = s.heap.back();
      s.heap.pop_back();
      if (dv > s.dist[x]) continue;
      if (s.vertexStamp[x] != v) {
        s.vertexStamp[x] = v;
        s.reached.push_back(x);
      }
      for (int k = adjStart_[x]; k < adjStart_[x + 1]; ++k) {
        const auto [y, len] = adj_[k];
        const double dy = dv + len;
        if (dy <= reach_ && dy < s.dist[y]) {
          s.dist[y] = dy;
          s.heap.push_back({dy, y});
          std::push_heap(s.heap.begin(), s.heap.end(), later);
        }
      }
    }
  }

  void measureBall(int v, Scratch& s, CurvatureMeasureResult& r) const {
    grow(v, s);
    auto distanceOf = [&](int x) { return s.vertexStamp[x] == v ? s.dist[x] : INFINITY; };
    const RegionCurvatureMeasure b = region_ == MeasureRegion::GeodesicBall
                                         ? ctx_.sublevelSet(s.reached, distanceOf, radius_, v, s.faceStamp)
                                         : ctx_.triangleUnion(s.reached, distanceOf, radius_, v, s.faceStamp);
    for (int x : s.reached) s.dist[x] = INFINITY;
    r.discrete[v] = b.discrete;
    r.smooth[v] = b.smooth;
    r.absoluteScale[v] = b.absoluteScale;
    r.relativeError[v] = b.absoluteScale > 0 ? (b.discrete - b.smooth) / b.absoluteScale : 0.0;
  }

  const MeasureContext& ctx_;
  const HalfedgeMesh& m_;
  double radius_, reach_ = 0;
  MeasureRegion region_;
  std::vector<int> adjStart_;
  std::vector<std::pair<int, double>> adj_;
  mutable std::mutex poolMutex_;
  mutable std::vector<std::unique_ptr<Scratch>> pool_;
};

// The exact all-vertex check, GeodesicBall regions, with the results of BallSweep to round-off (docs/theory.md §5,
// "Cost"): the centres are grouped into patches of up to kLanes nearby vertices, and one label-correcting Dijkstra per
// patch carries the kLanes distance fields side by side (a vertex's lanes contiguous), so that the queue's cost is
// shared by the patch and a relaxation is a loop over lanes. Its distances are BallSweep's bit for bit: both are the
// least fixed point of d(y) = min_x fl(d(x) + ℓ(xy)) below the reach, i.e. the minimum over edge paths of the
// floating-point sum taken from the centre. The sums then add the same terms as BallSweep's, in another order: the
// terms that are inside for every lane (a vertex's atom, a face's whole integral) once into a sum common to the patch,
// the others lane by lane (the rim annulus). Every patch is independent, so the threads do not change the result.
//
// For speed the sweep works on its own copy of the mesh's connectivity, renumbered in patch order (vertex i of the
// copy is centres_[i]; faces numbered by first appearance in those vertices' fans), so that the loads of a Dijkstra
// are near one another: neighbours, edge lengths, atoms, fans and face integrals in compact arrays (structure of
// arrays). The renumbering keeps every list's order, and slots are numbered in discovery order, so the pop order, the
// slots and every sum's order are those of the plain numbering: the results are the same bits. A relaxation is 16
// lanes of add, compare and select, four at a time (relaxLanes).
// Four distance lanes, for PatchSweep's relaxation.
typedef double LaneQuad __attribute__((vector_size(32)));

class PatchSweep {
 public:
  static constexpr int kLanes = 16;

  PatchSweep(const MeasureContext& ctx, const IntrinsicTriangulation& mesh, double radius)
      : ctx_(ctx), m_(mesh.mesh), radius_(radius) {
    reach_ = radius + *std::max_element(mesh.edgeLengths.begin(), mesh.edgeLengths.end());
    const Neighbours nbr = flattenNeighbours(mesh);
    unreached_.fill(INFINITY);
    buildPatches(nbr);
    renumberVertices(nbr);
    renumberFaces();
  }

  // Fills r.discrete, r.smooth, r.absoluteScale and r.relativeError for every vertex, in blocks of a hundredth of the
  // patches (progress, counted in centres, after each).
  void run(CurvatureMeasureResult& r, const std::function<void(int, int)>& progress) const {
    const int nP = static_cast<int>(patchStart_.size()) - 1, nV = m_.nVertices(), block = (nP + 99) / 100;
    for (int b0 = 0; b0 < nP; b0 += block) {
      const int b1 = std::min(nP, b0 + block);
      constexpr int kChunks = 8;
      runChunks(kChunks, [&](int c) {
        std::unique_ptr<Scratch> s = takeScratch();
        for (int p = b0 + (b1 - b0) * c / kChunks; p < b0 + (b1 - b0) * (c + 1) / kChunks; ++p) measurePatch(p, *s, r);
        giveScratch(std::move(s));
      });
      if (progress) progress(b1 == nP ? nV : patchStart_[b1], nV);
    }
  }

 private:
  // Where vertex x (sweep numbering) sits in the current patch: its slot, valid when stamp == the patch.
  struct SlotRef {
    int stamp = -1, slot = -1;
  };

  // Per-thread work arrays of one patch: its vertices by local slot, their lane distances (slot x's lanes at
  // dist[kLanes x, kLanes x + kLanes)), the queue.
  struct Scratch {
    std::vector<SlotRef> ref;       // per vertex
    std::vector<int> faceStamp;     // per face
    std::vector<int> verts, faces;  // slot → vertex; the faces touching the region
    std::vector<double> dist;
    std::vector<double> lo, hi, pendingKey;  // per slot: min and max over the patch's lanes; queued key
    std::vector<char> pending;
    std::vector<std::pair<double, int>> heap;  // (key, slot)
  };

  // Patches: seeds taken in breadth-first order over the mesh, each grown breadth-first over the vertices not yet in a
  // patch until it holds kLanes (fewer where they run out), so consecutive patches are neighbours.
  void buildPatches(const Neighbours& nbr) {
    const int nV = m_.nVertices();
    std::vector<int> order;
    order.reserve(nV);
    std::vector<char> seen(nV, 0), taken(nV, 0);
    for (int s = 0; s < nV; ++s) {
      if (seen[s]) continue;
      seen[s] = 1;
      order.push_back(s);
      for (size_t q = order.size() - 1; q < order.size(); ++q)
        for (int k = nbr.start[order[q]]; k < nbr.start[order[q] + 1]; ++k) {
          const int y = nbr.list[k].first;
          if (!seen[y]) seen[y] = 1, order.push_back(y);
        }
    }
    std::vector<int> grow;
    patchStart_.assign(1, 0);
    for (int seed : order) {
      if (taken[seed]) continue;
      grow.assign(1, seed);
      taken[seed] = 1;
      for (size_t q = 0; q < grow.size() && static_cast<int>(grow.size()) < kLanes; ++q)
        for (int k = nbr.start[grow[q]]; k < nbr.start[grow[q] + 1] && static_cast<int>(grow.size()) < kLanes; ++k) {
          const int y = nbr.list[k].first;
          if (!taken[y]) taken[y] = 1, grow.push_back(y);
        }
      centres_.insert(centres_.end(), grow.begin(), grow.end());
      patchStart_.push_back(static_cast<int>(centres_.size()));
    }
  }

  // The sweep numbering: vertex i is centres_[i] (every vertex is in exactly one patch). The neighbour lists keep
  // their order, with the edge lengths in an array of their own.
  void renumberVertices(const Neighbours& nbr) {
    const int nV = m_.nVertices();
    newOf_.assign(nV, -1);
    for (int i = 0; i < nV; ++i) newOf_[centres_[i]] = i;
    adjStart_.assign(nV + 1, 0);
    adjTo_.reserve(nbr.list.size());
    adjLen_.reserve(nbr.list.size());
    atom_.resize(nV);
    boundary_.resize(nV);
    for (int i = 0; i < nV; ++i) {
      const int g = centres_[i];
      for (int k = nbr.start[g]; k < nbr.start[g + 1]; ++k) {
        adjTo_.push_back(newOf_[nbr.list[k].first]);
        adjLen_.push_back(nbr.list[k].second);
      }
      adjStart_[i + 1] = static_cast<int>(adjTo_.size());
      atom_[i] = ctx_.atom[g];
      boundary_[i] = ctx_.boundaryTerms && m_.isBoundaryVertex(g);
    }
  }

  // Faces numbered by first appearance in the renumbered vertices' fans (fan order kept), with their three vertices
  // (sweep numbering, the mesh's corner order) and whole-face integrals alongside.
  void renumberFaces() {
    const int nV = m_.nVertices(), nF = m_.nFaces();
    std::vector<int> newFace(nF, -1);
    fanStart_.assign(nV + 1, 0);
    fanFaces_.reserve(ctx_.fanFaces.size());
    faceOld_.reserve(nF);
    for (int i = 0; i < nV; ++i) {
      const int g = centres_[i];
      for (int fk = ctx_.fanStart[g]; fk < ctx_.fanStart[g + 1]; ++fk) {
        const int f = ctx_.fanFaces[fk];
        if (newFace[f] < 0) newFace[f] = static_cast<int>(faceOld_.size()), faceOld_.push_back(f);
        fanFaces_.push_back(newFace[f]);
      }
      fanStart_[i + 1] = static_cast<int>(fanFaces_.size());
    }
    const int nUsed = static_cast<int>(faceOld_.size());
    faceVerts_.resize(3 * static_cast<size_t>(nUsed));
    faceIntegral_.resize(nUsed);
    faceAbs_.resize(nUsed);
    faceDensity_.resize(nUsed);
    for (int f = 0; f < nUsed; ++f) {
      const int g = faceOld_[f];
      for (int k = 0; k < 3; ++k) faceVerts_[3 * f + k] = newOf_[m_.faceVertex(g, k)];
      faceIntegral_[f] = ctx_.face[g].integral;
      faceAbs_[f] = ctx_.face[g].absIntegral;
      faceDensity_[f] = ctx_.face[g];
    }
  }

  std::unique_ptr<Scratch> takeScratch() const {
    std::lock_guard<std::mutex> lock(poolMutex_);
    if (pool_.empty()) {
      auto s = std::make_unique<Scratch>();
      s->ref.assign(m_.nVertices(), SlotRef{});
      s->faceStamp.assign(faceOld_.size(), -1);
      return s;
    }
    std::unique_ptr<Scratch> s = std::move(pool_.back());
    pool_.pop_back();
    return s;
  }
  void giveScratch(std::unique_ptr<Scratch> s) const {
    std::lock_guard<std::mutex> lock(poolMutex_);
    pool_.push_back(std::move(s));
  }

  int slot(int x, int patch, Scratch& s) const {
    SlotRef& ref = s.ref[x];
    if (ref.stamp == patch) return ref.slot;
    ref.stamp = patch;
    ref.slot = static_cast<int>(s.verts.size());
    s.verts.push_back(x);
    s.dist.insert(s.dist.end(), kLanes, INFINITY);
    s.pending.push_back(0);
    s.pendingKey.push_back(INFINITY);
    return ref.slot;
  }

  void enqueue(int y, double key, Scratch& s) const {
    if (s.pending[y] && s.pendingKey[y] <= key) return;  // it will be relaxed with its current lanes anyway
    s.pending[y] = 1;
    s.pendingKey[y] = key;
    s.heap.push_back({key, y});
    std::push_heap(s.heap.begin(), s.heap.end(), std::greater<std::pair<double, int>>());
  }

  // dy[c] = min(dy[c], dx[c] + len) for the lanes where dx[c] + len ≤ reach; returns the least improved lane's new
  // value (∞ if none). Branch-free on four lanes at a time (GCC vector extensions: two SSE2 instructions each in the
  // default build, one AVX2 instruction in grow's AVX2 clone); add, compare and select are exact per lane, so the
  // width cannot change a bit.
  __attribute__((always_inline)) double relaxLanes(const double* dx, double* dy, double len) const {
    const LaneQuad l = {len, len, len, len}, reach = {reach_, reach_, reach_, reach_};
    const LaneQuad inf = {INFINITY, INFINITY, INFINITY, INFINITY};
    LaneQuad best = inf;
    for (int c = 0; c < kLanes; c += 4) {
      LaneQuad from, old;
      std::memcpy(&from, dx + c, sizeof from);
      std::memcpy(&old, dy + c, sizeof old);
      const LaneQuad d = from + l;
      const LaneQuad capped = d <= reach ? d : inf;
      const LaneQuad improved = capped < old ? capped : inf;
      const LaneQuad updated = capped < old ? capped : old;
      std::memcpy(dy + c, &updated, sizeof updated);
      best = improved < best ? improved : best;
    }
    const double b01 = best[0] < best[1] ? best[0] : best[1], b23 = best[2] < best[3] ? best[2] : best[3];
    return b01 < b23 ? b01 : b23;
  }

  // The label-correcting Dijkstra of patch p: a slot is queued at the least of its lanes that improved, and relaxes
  // all its lanes when popped; it ends when no lane improves, at the least fixed point (the class comment).
  __attribute__((target_clones("avx2", "default"))) void grow(int p, Scratch& s) const {
    s.verts.clear(), s.dist.clear(), s.pending.clear(), s.pendingKey.clear(), s.heap.clear();
    for (int c = 0; c < patchStart_[p + 1] - patchStart_[p]; ++c) {
      const int x = slot(patchStart_[p] + c, p, s);
      s.dist[kLanes * static_cast<size_t>(x) + c] = 0;
      enqueue(x, 0.0, s);
    }
    const auto later = std::greater<std::pair<double, int>>();
    while (!s.heap.empty()) {
      std::pop_heap(s.heap.begin(), s.heap.end(), later);
      const int x = s.heap.back().second;
      s.heap.pop_back();
      if (!s.pending[x]) continue;
      s.pending[x] = 0;
      const int gx = s.verts[x];
      for (int k = adjStart_[gx]; k < adjStart_[gx + 1]; ++k) {
        const int y = slot(adjTo_[k], p, s);  // may grow s.dist: take its address after
        const double best =
            relaxLanes(&s.dist[kLanes * static_cast<size_t>(x)], &s.dist[kLanes * static_cast<size_t>(y)], adjLen_[k]);
        if (best < INFINITY) enqueue(y, best, s);
      }
    }
    const size_t n = s.verts.size();
    s.lo.resize(n);
    s.hi.resize(n);
    for (size_t x = 0; x < n; ++x) {
      const double* d = &s.dist[kLanes * x];
      s.lo[x] = *std::min_element(d, d + kLanes);
      s.hi[x] = *std::max_element(d, d + kLanes);
    }
  }

  void measurePatch(int p, Scratch& s, CurvatureMeasureResult& r) const {
    grow(p, s);
    const int lanes = patchStart_[p + 1] - patchStart_[p];
    std::array<RegionCurvatureMeasure, kLanes> lane{};
    RegionCurvatureMeasure common;
    sumVertices(p, s, lanes, common, lane);
    sumFaces(p, s, lanes, common, lane);
    for (int c = 0; c < lanes; ++c) {
      const int v = centres_[patchStart_[p] + c];
      const RegionCurvatureMeasure& b = lane[c];
      r.discrete[v] = common.discrete + b.discrete;
      r.smooth[v] = common.smooth + b.smooth;
      r.absoluteScale[v] = common.absoluteScale + b.absoluteScale;
      r.relativeError[v] = r.absoluteScale[v] > 0 ? (r.discrete[v] - r.smooth[v]) / r.absoluteScale[v] : 0.0;
    }
  }

  // The distance of vertex x (sweep numbering) in lane c of patch p (infinite where the patch never reached it).
  double distance(int x, int c, int p, const Scratch& s) const {
    const SlotRef& ref = s.ref[x];
    return ref.stamp == p ? s.dist[kLanes * static_cast<size_t>(ref.slot) + c] : INFINITY;
  }

  void sumVertices(int p, Scratch& s, int lanes, RegionCurvatureMeasure& common,
                   std::array<RegionCurvatureMeasure, kLanes>& lane) const {
    for (size_t x = 0; x < s.verts.size(); ++x) {
      if (s.lo[x] >= radius_) continue;
      const int i = s.verts[x];
      const bool boundary = boundary_[i];
      if (s.hi[x] < radius_ && !boundary) {
        common.discrete += atom_[i];
        continue;
      }
      const double* d = &s.dist[kLanes * x];
      for (int c = 0; c < lanes; ++c) {
        if (d[c] >= radius_) continue;
        lane[c].discrete += atom_[i];
        if (boundary)
          ctx_.addBoundaryAtoms(
              centres_[i], [&](int y) { return distance(newOf_[y], c, p, s); }, radius_, lane[c]);
      }
    }
  }

  __attribute__((target_clones("avx2", "default"))) void sumFaces(
      int p, Scratch& s, int lanes, RegionCurvatureMeasure& common,
      std::array<RegionCurvatureMeasure, kLanes>& lane) const {
    s.faces.clear();
    for (size_t x = 0; x < s.verts.size(); ++x) {
      if (s.lo[x] >= radius_) continue;
      const int i = s.verts[x];
      for (int fk = fanStart_[i]; fk < fanStart_[i + 1]; ++fk) {
        const int f = fanFaces_[fk];
        if (s.faceStamp[f] != p) s.faceStamp[f] = p, s.faces.push_back(f);
      }
    }
    // The rim faces lane by lane, four lanes at a time: per lane the same operations in the same face order as
    // addFace (a whole face's integrals added where its three vertices are inside, addFaceShare where the rim cuts it).
    std::array<double, kLanes> smooth, scale;
    for (int c = 0; c < kLanes; ++c) smooth[c] = lane[c].smooth, scale[c] = lane[c].absoluteScale;
    const LaneQuad r = {radius_, radius_, radius_, radius_};
    for (int f : s.faces) {
      const double* row[3];
      double hi = 0;
      for (int k = 0; k < 3; ++k) {
        const SlotRef& ref = s.ref[faceVerts_[3 * f + k]];
        const bool reached = ref.stamp == p;
        row[k] = reached ? &s.dist[kLanes * static_cast<size_t>(ref.slot)] : unreached_.data();
        hi = std::max(hi, reached ? s.hi[ref.slot] : INFINITY);
      }
      if (hi < radius_) {
        common.smooth += faceIntegral_[f];
        common.absoluteScale += faceAbs_[f];
        continue;
      }
      const double w = faceIntegral_[f], wa = faceAbs_[f];
      const LaneQuad whole = {w, w, w, w}, wholeAbs = {wa, wa, wa, wa};
      for (int c = 0; c < kLanes; c += 4) {
        LaneQuad d0, d1, d2, sm, sc;
        std::memcpy(&d0, row[0] + c, sizeof d0);
        std::memcpy(&d1, row[1] + c, sizeof d1);
        std::memcpy(&d2, row[2] + c, sizeof d2);
        std::memcpy(&sm, &smooth[c], sizeof sm);
        std::memcpy(&sc, &scale[c], sizeof sc);
        const auto inside = (d0 < r) + (d1 < r) + (d2 < r);  // −(number of vertices inside), per lane
        sm = inside == -3 ? sm + whole : sm;
        sc = inside == -3 ? sc + wholeAbs : sc;
        std::memcpy(&smooth[c], &sm, sizeof sm);
        std::memcpy(&scale[c], &sc, sizeof sc);
        const auto cut = (inside != 0) & (inside != -3);
        for (int j = 0; j < 4; ++j) {
          if (!cut[j] || c + j >= lanes) continue;
          const int lc = c + j;
          const double d[3] = {row[0][lc], row[1][lc], row[2][lc]};
          RegionCurvatureMeasure out{0, smooth[lc], scale[lc]};
          MeasureContext::addFaceShare(faceDensity_[f], d, radius_, out);
          smooth[lc] = out.smooth, scale[lc] = out.absoluteScale;
        }
      }
    }
    for (int c = 0; c < kLanes; ++c) lane[c].smooth = smooth[c], lane[c].absoluteScale = scale[c];
  }

  const MeasureContext& ctx_;
  const HalfedgeMesh& m_;
  double radius_, reach_ = 0;
  std::vector<int> patchStart_, centres_;  // patch p's centres: centres_[patchStart_[p], patchStart_[p+1])
  // The sweep numbering (the class comment): vertex i is mesh vertex centres_[i], newOf_ the inverse.
  std::vector<int> newOf_, adjStart_, adjTo_;
  std::vector<double> adjLen_, atom_;
  std::vector<char> boundary_;                  // boundary vertex with boundary terms
  std::vector<int> fanStart_, fanFaces_;        // per vertex, its faces in fan order (sweep face numbers)
  std::vector<int> faceOld_, faceVerts_;        // sweep face → mesh face; its three vertices
  std::vector<double> faceIntegral_, faceAbs_;  // ∫K dA and ∫|K| dA over the face's image
  std::vector<FaceDensity> faceDensity_;        // for the faces a rim cuts
  std::array<double, kLanes> unreached_;        // the lanes of a vertex the patch never reached: all ∞
  mutable std::mutex poolMutex_;
  mutable std::vector<std::unique_ptr<Scratch>> pool_;
};

}  // namespace

QuadratureResult integrateOverReferenceTriangle(const SmoothMetric& metric, const ChartFunction& density,
                                                const Eigen::Vector3d& xa, const Eigen::Vector3d& xbIn,
                                                const Eigen::Vector3d& xcIn, const QuadratureOptions& options) {
  const ChartDomain d = metric.domain();
  const Eigen::Vector3d xb = unwrapNear(d, xa, xbIn), xc = unwrapNear(d, xa, xcIn);
  const Eigen::Vector3d es = xb - xa, et = xc - xa;
  // x(s, t) = xa + s·es + t·et on the unit triangle; on the reference sphere chartPoint reads only the direction of x,
  // so this is the gnomonic parametrization of the geodesic triangle. The density is pulled back with |det
  // ∂(u,v)/∂(s,t)|.
  const ChartFunction pulledBack = [&](double s, double t) {
    const Eigen::Vector3d x = xa + s * es + t * et;
    Eigen::Vector2d ds, dt;
    chartPoint(d, x, es, &ds);
    chartPoint(d, x, et, &dt);
    const Eigen::Vector2d uv = chartCoordinates(d, x);
    return density(uv.x(), uv.y()) * std::abs(ds.x() * dt.y() - ds.y() * dt.x());
  };
  return integrateOverTriangle(pulledBack, {0, 0}, {1, 0}, {0, 1}, options);
}

double geodesicCurvature(const SmoothMetric& metric, const Eigen::Vector2d& uv, const Eigen::Vector2d& velocity,
                         const Eigen::Vector2d& acceleration) {
  const CurvatureTerms k = curvatureTerms(metric.jet(uv.x(), uv.y()), velocity, acceleration);
  return k.signedTurn / (k.speed2 * std::sqrt(k.speed2));
}

RegionCurvatureMeasure curvatureMeasureOfSublevelSet(const IntrinsicTriangulation& mesh,
                                                     const std::vector<Eigen::Vector3d>& referencePoints,
                                                     const SmoothMetric& metric, const std::vector<double>& level,
                                                     double r, const CurvatureMeasureOptions& options) {
  const MeasureContext ctx(mesh, referencePoints, metric, options.boundaryTerms);
  const int nV = mesh.mesh.nVertices();
  if (static_cast<int>(level.size()) != nV)
    throw InputError("curvature measure: expected one level value per vertex (" + std::to_string(nV) + "), found " +
                     std::to_string(level.size()));
  for (int v = 0; v < nV; ++v)
    if (!std::isfinite(level[v]))
      throw InputError("curvature measure: the level of vertex " + std::to_string(v) + " is not finite");
  std::vector<int> all(nV), faceStamp(mesh.mesh.nFaces(), -1);
  for (int v = 0; v < nV; ++v) all[v] = v;
  return ctx.sublevelSet(
      all, [&](int x) { return level[x]; }, r, 0, faceStamp);
}

std::string CurvatureMeasureOptions::validate() const {
  if (!(radiusFraction > 0))
    return "curvature measure: the ball radius fraction must be positive, found " + std::to_string(radiusFraction);
  if (sampleCentres < 0)
    return "curvature measure: the number of sampled centres must be 0 (every vertex) or positive, found " +
           std::to_string(sampleCentres);
  if (histogramBins < 1)
    return "curvature measure: expected at least one histogram bin, found " + std::to_string(histogramBins);
  if (!(histogramRange > 0))
    return "curvature measure: the histogram range must be positive, found " + std::to_string(histogramRange);
  return "";
}

namespace {

// n distinct vertices of [0, nV) uniformly without replacement, ascending: a partial Fisher–Yates shuffle driven by
// SplitMix64 (Steele–Lea–Flood 2014), the index the floor of a 53-bit uniform times the range (bias below 2⁻²² for
// nV < 2³¹), in IEEE arithmetic only, so a seed gives the same centres on every platform.
std::vector<int> sampleVertices(int nV, int n, unsigned long long seed) {
  std::vector<int> perm(nV);
  for (int v = 0; v < nV; ++v) perm[v] = v;
  std::uint64_t state = seed;
  auto next = [&state] {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  for (int i = 0; i < n; ++i) {
    const double uniform = static_cast<double>(next() >> 11) * 0x1.0p-53;  // in [0, 1), 53 random bits
    const int j = i + std::min(nV - i - 1, static_cast<int>(uniform * (nV - i)));
    std::swap(perm[i], perm[j]);
  }
  perm.resize(n);
  std::sort(perm.begin(), perm.end());
  return perm;
}

// e_G, its maximum, the band fraction and the histogram over the measured centres; in sampled mode also the 95 %
// confidence half-width of e_G (the header).
void summarize(const std::vector<int>& centres, int nV, const CurvatureMeasureOptions& options,
               CurvatureMeasureResult& r) {
  r.histogram.assign(options.histogramBins, 0);
  int within = 0;
  double sumAbs = 0, sumSq = 0;
  for (int v : centres) {
    const double err = std::abs(r.discrete[v] - r.smooth[v]);
    sumAbs += err;
    sumSq += err * err;
    r.maxAbsoluteError = std::max(r.maxAbsoluteError, err);
    const double rel = r.relativeError[v];
    within += std::abs(rel) < options.withinBand;
    const double t = (rel + options.histogramRange) / (2 * options.histogramRange);
    const int bin = std::clamp(static_cast<int>(std::floor(t * options.histogramBins)), 0, options.histogramBins - 1);
    ++r.histogram[bin];
  }
  const int n = static_cast<int>(centres.size());
  r.meanAbsoluteError = sumAbs / n;
  r.fractionWithinBand = static_cast<double>(within) / n;
  if (n < nV && n > 1) {
    const double variance = std::max(0.0, (sumSq - n * r.meanAbsoluteError * r.meanAbsoluteError) / (n - 1));
    r.meanAbsoluteErrorHalfWidth = 1.96 * std::sqrt(variance / n) * std::sqrt(static_cast<double>(nV - n) / (nV - 1));
  }
}

}  // namespace

CurvatureMeasureResult gaussianCurvatureMeasure(const IntrinsicTriangulation& mesh,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const SmoothMetric& metric, const CurvatureMeasureOptions& options) {
  const HalfedgeMesh& m = mesh.mesh;
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);
  const MeasureContext ctx(mesh, referencePoints, metric, options.boundaryTerms);
  CurvatureMeasureResult r;
  r.smoothTotalCurvature = ctx.smoothTotal;
  r.smoothBoundaryCurvature = ctx.smoothBoundary;

  // === the regions
  r.radius = options.radiusFraction * std::sqrt(totalArea(mesh));
  const int nV = m.nVertices();
  const bool sampled = options.sampleCentres > 0 && options.sampleCentres < nV;
  const double unmeasured = sampled ? NAN : 0.0;
  r.discrete.assign(nV, unmeasured);
  r.smooth.assign(nV, unmeasured);
  r.absoluteScale.assign(nV, unmeasured);
  r.relativeError.assign(nV, unmeasured);
  std::vector<int> centres;
  if (sampled) {
    centres = sampleVertices(nV, options.sampleCentres, options.sampleSeed);
    BallSweep(ctx, mesh, r.radius, options.region).run(centres, r, options.progress);
    r.centres = centres;
  } else {
    centres.resize(nV);
    for (int v = 0; v < nV; ++v) centres[v] = v;
    if (options.algorithm == BallSweepAlgorithm::Patches && options.region == MeasureRegion::GeodesicBall)
      PatchSweep(ctx, mesh, r.radius).run(r, options.progress);
    else
      BallSweep(ctx, mesh, r.radius, options.region).run(centres, r, options.progress);
  }

  // === statistics
  summarize(centres, nV, options, r);
  return r;
}

}  // namespace conformesh::intrinsic
