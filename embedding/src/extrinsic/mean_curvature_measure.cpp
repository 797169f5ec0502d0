// mean_curvature_measure.cpp — eq. 2 on the mesh and ∫(κ₁ + κ₂) dA on the surface over the balls B(v, r), with the
// smooth side assembled from pre-integrated sub-triangles of the triangles' images (see mean_curvature_measure.h).
#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::HalfedgeMesh;
using intrinsic::kInvalid;

namespace {

// Share of a triangle's area where the linear function with corner values φ is negative.
double negativeShare(const std::array<double, 3>& phi) {
  int neg = 0;
  for (double p : phi) neg += p < 0;
  if (neg == 0) return 0;
  if (neg == 3) return 1;
  // The corner i alone on its side: the region on its side is the triangle cut off at the zero crossings along its
  // two edges, a fraction φᵢ² / ((φᵢ − φⱼ)(φᵢ − φₖ)) of the area.
  int i = 0;
  for (int k = 0; k < 3; ++k)
    if ((phi[k] < 0) == (neg == 1)) i = k;
  const double pi = phi[i], pj = phi[(i + 1) % 3], pk = phi[(i + 2) % 3];
  const double corner = pi * pi / ((pi - pj) * (pi - pk));
  return neg == 1 ? corner : 1 - corner;
}

// A uniform grid over R³ holding vertex indices, to find the vertices near a ball centre.
class VertexGrid {
 public:
  VertexGrid(const std::vector<Eigen::Vector3d>& p, double cell) : p_(p), cell_(cell) {
    for (int v = 0; v < static_cast<int>(p.size()); ++v) cells_[key(cellOf(p[v]))].push_back(v);
  }
  template <class F>
  void forEachWithin(const Eigen::Vector3d& c, double radius, F&& f) const {
    const Eigen::Vector3i lo = cellOf(c - Eigen::Vector3d::Constant(radius));
    const Eigen::Vector3i hi = cellOf(c + Eigen::Vector3d::Constant(radius));
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z) {
          const auto it = cells_.find(key({x, y, z}));
          if (it == cells_.end()) continue;
          for (int v : it->second)
            if ((p_[v] - c).norm() <= radius) f(v);
        }
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const {
    return {static_cast<int>(std::floor(x.x() / cell_)), static_cast<int>(std::floor(x.y() / cell_)),
            static_cast<int>(std::floor(x.z() / cell_))};
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::int64_t>(c.x() & 0x1fffff) << 42) | (static_cast<std::int64_t>(c.y() & 0x1fffff) << 21) |
           static_cast<std::int64_t>(c.z() & 0x1fffff);
  }
  const std::vector<Eigen::Vector3d>& p_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace

double signedDihedralAngle(const HalfedgeMesh& mesh, const std::vector<Eigen::Vector3d>& x, int e) {
  const int h = mesh.edgeHalfedge(e), t = mesh.twin(h);
  if (t == kInvalid) return 0;
  const Eigen::Vector3d& a = x[mesh.tail(h)];
  const Eigen::Vector3d& b = x[mesh.tip(h)];
  const Eigen::Vector3d& c = x[mesh.tip(HalfedgeMesh::next(h))];
  const Eigen::Vector3d& d = x[mesh.tip(HalfedgeMesh::next(t))];
  const Eigen::Vector3d n1 = (b - a).cross(c - a).normalized(), n2 = (a - b).cross(d - b).normalized();
  return std::atan2(n1.cross(n2).dot((b - a).normalized()), n1.dot(n2));
}

double segmentLengthInBall(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double r) {
  // |a + t(b − a) − c|² = r²: A t² + 2B t + C = 0; the chord is [t₁, t₂] ∩ [0, 1].
  const Eigen::Vector3d d = b - a, m = a - c;
  const double A = d.squaredNorm(), B = m.dot(d), C = m.squaredNorm() - r * r;
  if (A == 0) return 0;
  const double disc = B * B - A * C;
  if (disc <= 0) return 0;
  const double s = std::sqrt(disc);
  const double t1 = std::max(0.0, (-B - s) / A), t2 = std::min(1.0, (-B + s) / A);
  return t2 > t1 ? (t2 - t1) * std::sqrt(A) : 0.0;
}

MeanCurvatureMeasureResult meanCurvatureMeasure(const intrinsic::IntrinsicTriangulation& tri,
                                                const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const EmbeddedSurface& surface,
                                                const MeanCurvatureMeasureOptions& options) {
  const auto& mesh = tri.mesh;
  const int nV = mesh.nVertices(), nF = mesh.nFaces(), nE = mesh.nEdges();
  if (static_cast<int>(positions.size()) != nV || static_cast<int>(referencePoints.size()) != nV)
    throw InputError("mean curvature measure: " + std::to_string(positions.size()) + " positions and " +
                     std::to_string(referencePoints.size()) + " reference points for " + std::to_string(nV) +
                     " vertices");
  for (int v = 0; v < nV; ++v)
    if (!positions[v].allFinite() || !referencePoints[v].allFinite())
      throw InputError("mean curvature measure: vertex " + std::to_string(v) +
                       " has a non-finite position or reference point");
  if (tri.background != intrinsic::Background::Euclidean)
    throw InputError("mean curvature measure: the mesh must be Euclidean (a mesh in R³), found " +
                     intrinsic::toString(tri.background));
  if (options.subdivision < 0 || options.subdivision > 6)
    throw InputError("mean curvature measure: subdivision must be in 0..6, found " +
                     std::to_string(options.subdivision));
  if (!(options.radiusFraction > 0) || options.histogramBins < 1 || !(options.histogramRange > 0))
    throw InputError("mean curvature measure: radius fraction and histogram range must be positive, bins ≥ 1");

  MeanCurvatureMeasureResult r;
  double area = 0, longest = 0;
  for (int f = 0; f < nF; ++f) {
    const auto& a = positions[mesh.faceVertex(f, 0)];
    const auto& b = positions[mesh.faceVertex(f, 1)];
    const auto& c = positions[mesh.faceVertex(f, 2)];
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  std::vector<double> beta(nE), length(nE);
  for (int e = 0; e < nE; ++e) {
    const int h = mesh.edgeHalfedge(e);
    beta[e] = signedDihedralAngle(mesh, positions, e);
    length[e] = (positions[mesh.tip(h)] - positions[mesh.tail(h)]).norm();
    longest = std::max(longest, length[e]);
    r.discreteTotal += length[e] * beta[e];
  }
  r.radius = options.radiusFraction * std::sqrt(area);

  // === the smooth side, pre-integrated on sub-triangles of each triangle's image
  // Grid point (i, j), i + j ≤ n, of a triangle is its barycentric place (1 − (i+j)/n, i/n, j/n).
  const int n = 1 << options.subdivision;
  const int gridPoints = (n + 1) * (n + 2) / 2, subTriangles = n * n;
  auto gridIndex = [n](int i, int j) { return j * (n + 1) - j * (j - 1) / 2 + i; };
  // Sub-triangles as grid-point triples: "up" (i,j),(i+1,j),(i,j+1) and "down" (i+1,j),(i+1,j+1),(i,j+1).
  std::vector<std::array<Eigen::Vector2i, 3>> sub;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      sub.push_back({Eigen::Vector2i(i, j), Eigen::Vector2i(i + 1, j), Eigen::Vector2i(i, j + 1)});
      if (i + j + 1 < n)
        sub.push_back({Eigen::Vector2i(i + 1, j), Eigen::Vector2i(i + 1, j + 1), Eigen::Vector2i(i, j + 1)});
    }
  std::vector<Eigen::Vector3d> gridPos(static_cast<std::size_t>(nF) * gridPoints);
  // Per sub-triangle k and edge m (from corner m to corner m+1): the surface point at the edge midpoint and the
  // densities (κ₁ + κ₂)·|X_s × X_t| and |κ₁ + κ₂|·|X_s × X_t| there.
  const std::size_t nodes = static_cast<std::size_t>(nF) * subTriangles * 3;
  std::vector<Eigen::Vector3d> midPos(nodes);
  std::vector<double> midH(nodes), midAbsH(nodes);
  const double subArea = 0.5 / (n * n);  // (s, t)-area of a sub-triangle
  for (int f = 0; f < nF; ++f) {
    const Eigen::Vector3d& ya = referencePoints[mesh.faceVertex(f, 0)];
    const Eigen::Vector3d e1 = referencePoints[mesh.faceVertex(f, 1)] - ya;
    const Eigen::Vector3d e2 = referencePoints[mesh.faceVertex(f, 2)] - ya;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i)
        gridPos[static_cast<std::size_t>(f) * gridPoints + gridIndex(i, j)] =
            surface.position(ya + (double(i) / n) * e1 + (double(j) / n) * e2);
    for (int k = 0; k < subTriangles; ++k) {
      // The density is (κ₁ + κ₂)·|X_s × X_t| for X(s, t) = position(ya + s e₁ + t e₂), whose normal X_s × X_t has the
      // triangle's orientation — the orientation the signs of β(e) refer to.
      double sum = 0;
      for (int m = 0; m < 3; ++m) {
        const Eigen::Vector2d st = (sub[k][m] + sub[k][(m + 1) % 3]).cast<double>() / (2.0 * n);
        const LocalSurfaceJet jet = surface.jet(ya + st.x() * e1 + st.y() * e2, e1, e2, true);
        const std::size_t id = (static_cast<std::size_t>(f) * subTriangles + k) * 3 + m;
        midPos[id] = jet.position;
        midH[id] = jet.meanCurvature * jet.areaFactor;
        midAbsH[id] = std::abs(jet.meanCurvature) * jet.areaFactor;
        sum += midH[id];
      }
      // Degree-2 rule: area/3 × Σ of the density at the three edge midpoints.
      r.smoothTotal += sum * subArea / 3;
    }
  }

  // Sub-triangle k of face f inside B(c, r): all of it, none of it, or — when its six nodes (corners and edge
  // midpoints) lie on both sides of the sphere — the part where the quadratic (P2) interpolant of |X − c| − r through
  // the six nodes is negative, found by splitting the sub-triangle into kMini² pieces and clipping each with the
  // linear interpolant of its corner values; the density over it is the linear function through the three midpoint
  // values (the one the degree-2 rule integrates exactly). The P2 rim is off by O(h³) where the linear one was off by
  // O(h²): with h/r ≈ 0.25 at the coarsest meshes, the smooth ball measure of the sphere comes out to ≈ 1e-4.
  constexpr int kMini = 8;
  auto subIntegral = [&](int f, int k, const Eigen::Vector3d& c, double& valueH, double& valueAbsH) {
    const std::size_t base = (static_cast<std::size_t>(f) * subTriangles + k) * 3;
    std::array<double, 3> phiC, phiM;
    int negative = 0;
    for (int m = 0; m < 3; ++m) {
      phiC[m] =
          (gridPos[static_cast<std::size_t>(f) * gridPoints + gridIndex(sub[k][m].x(), sub[k][m].y())] - c).norm() -
          r.radius;
      phiM[m] = (midPos[base + m] - c).norm() - r.radius;
      negative += (phiC[m] < 0) + (phiM[m] < 0);
    }
    if (negative == 0) return;
    if (negative == 6) {
      valueH += subArea * (midH[base] + midH[base + 1] + midH[base + 2]) / 3;
      valueAbsH += subArea * (midAbsH[base] + midAbsH[base + 1] + midAbsH[base + 2]) / 3;
      return;
    }
    // λ = barycentric coordinates w.r.t. the sub-triangle's corners 0, 1, 2; midpoint m is between corners m, m+1.
    auto phiAt = [&](const Eigen::Vector3d& l) {
      double v = 0;
      for (int m = 0; m < 3; ++m) v += phiC[m] * l[m] * (2 * l[m] - 1) + phiM[m] * 4 * l[m] * l[(m + 1) % 3];
      return v;
    };
    auto densityAt = [&](const Eigen::Vector3d& l, const std::vector<double>& d) {
      // Linear, with value d_m at midpoint m: the midpoint opposite corner q is m = q + 1, and 1 − 2λ_q is 1 there, 0
      // at the other two midpoints.
      double v = 0;
      for (int q = 0; q < 3; ++q) v += d[base + (q + 1) % 3] * (1 - 2 * l[q]);
      return v;
    };
    const double miniArea = subArea / (kMini * kMini);
    for (int j = 0; j < kMini; ++j)
      for (int i = 0; i + j < kMini; ++i)
        for (int up = 0; up < 2; ++up) {
          if (up == 1 && i + j + 1 >= kMini) continue;
          std::array<Eigen::Vector2d, 3> g;
          if (up == 0)
            g = {Eigen::Vector2d(i, j), Eigen::Vector2d(i + 1, j), Eigen::Vector2d(i, j + 1)};
          else
            g = {Eigen::Vector2d(i + 1, j), Eigen::Vector2d(i + 1, j + 1), Eigen::Vector2d(i, j + 1)};
          std::array<double, 3> phi;
          Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
          for (int m = 0; m < 3; ++m) {
            const Eigen::Vector3d l(1 - (g[m].x() + g[m].y()) / kMini, g[m].x() / kMini, g[m].y() / kMini);
            phi[m] = phiAt(l);
            centroid += l / 3;
          }
          const double share = negativeShare(phi);
          if (share == 0) continue;
          valueH += share * miniArea * densityAt(centroid, midH);
          valueAbsH += share * miniArea * densityAt(centroid, midAbsH);
        }
  };

  // === per-vertex balls
  // A triangle or edge meeting B(v, r) has all its corners within r + (longest edge) of v; the images of triangles
  // are within O(ε²) of them, far inside that margin.
  const double reach = r.radius + longest;
  VertexGrid grid(positions, reach);
  std::vector<int> faceStamp(nF, -1), edgeStamp(nE, -1);
  r.discrete.assign(nV, 0);
  r.smooth.assign(nV, 0);
  r.absoluteScale.assign(nV, 0);
  r.relativeError.assign(nV, 0);
  for (int v = 0; v < nV; ++v) {
    const Eigen::Vector3d c = positions[v];
    double discrete = 0, smooth = 0, scale = 0;
    grid.forEachWithin(c, reach, [&](int w) {
      const int start = mesh.vertexHalfedge(w);
      int h = start;
      do {
        const int f = HalfedgeMesh::face(h);
        if (faceStamp[f] != v) {
          faceStamp[f] = v;
          for (int k = 0; k < 3; ++k) {
            const int hk = HalfedgeMesh::halfedge(f, k), e = mesh.edge(hk);
            if (edgeStamp[e] == v) continue;
            edgeStamp[e] = v;
            if (beta[e] != 0)
              discrete += beta[e] * segmentLengthInBall(positions[mesh.tail(hk)], positions[mesh.tip(hk)], c, r.radius);
          }
          for (int k = 0; k < subTriangles; ++k) subIntegral(f, k, c, smooth, scale);
        }
        h = mesh.nextOutgoing(h);
      } while (h != kInvalid && h != start);
    });
    r.discrete[v] = discrete;
    r.smooth[v] = smooth;
    r.absoluteScale[v] = scale;
    r.relativeError[v] = scale > 0 ? (discrete - smooth) / scale : 0.0;
  }

  // === statistics
  r.histogram.assign(options.histogramBins, 0);
  int within = 0;
  double sumAbs = 0, sumRel = 0;
  for (int v = 0; v < nV; ++v) {
    const double err = std::abs(r.discrete[v] - r.smooth[v]);
    sumAbs += err;
    r.maxAbsoluteError = std::max(r.maxAbsoluteError, err);
    const double rel = r.relativeError[v];
    sumRel += std::abs(rel);
    within += std::abs(rel) < options.withinBand;
    const double t = (rel + options.histogramRange) / (2 * options.histogramRange);
    const int bin = std::clamp(static_cast<int>(std::floor(t * options.histogramBins)), 0, options.histogramBins - 1);
    ++r.histogram[bin];
  }
  r.meanAbsoluteError = sumAbs / nV;
  r.meanRelativeError = sumRel / nV;
  r.fractionWithinBand = static_cast<double>(within) / nV;
  return r;
}

}  // namespace conformesh::embedding
