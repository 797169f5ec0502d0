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

// Sub-triangle k of face f inside B(c, r) is integrated as: all of it, none of it, or — when its six nodes (corners and
// edge midpoints) lie on both sides of the sphere — the part where the quadratic (P2) interpolant of |X − c| − r
// through the six nodes is negative, found by splitting the sub-triangle into kMini² pieces and clipping each with the
// linear interpolant of its corner values; the density over it is the linear function through the three midpoint
// values (the one the degree-2 rule integrates exactly). docs/embedding.md derives the O(h³) rim error.
constexpr int kMini = 8;

// The steps of meanCurvatureMeasure over their shared state: the mesh side (β, lengths), the smooth side
// pre-integrated on sub-triangles of each triangle's image, and the result being filled.
class MeanCurvatureMeasure {
 public:
  MeanCurvatureMeasure(const intrinsic::IntrinsicTriangulation& tri, const std::vector<Eigen::Vector3d>& positions,
                       const std::vector<Eigen::Vector3d>& referencePoints, const EmbeddedSurface& surface,
                       const MeanCurvatureMeasureOptions& options)
      : mesh_(tri.mesh),
        tri_(tri),
        positions_(positions),
        referencePoints_(referencePoints),
        surface_(surface),
        options_(options),
        nV_(mesh_.nVertices()),
        nF_(mesh_.nFaces()),
        nE_(mesh_.nEdges()) {}

  MeanCurvatureMeasureResult run() {
    checkInput();
    measureMesh();
    buildSubTriangles();
    preintegrateSurface();
    measureBalls();
    summarize();
    return std::move(r_);
  }

 private:
  void checkInput() const {
    if (static_cast<int>(positions_.size()) != nV_ || static_cast<int>(referencePoints_.size()) != nV_)
      throw InputError("mean curvature measure: " + std::to_string(positions_.size()) + " positions and " +
                       std::to_string(referencePoints_.size()) + " reference points for " + std::to_string(nV_) +
                       " vertices");
    for (int v = 0; v < nV_; ++v)
      if (!positions_[v].allFinite() || !referencePoints_[v].allFinite())
        throw InputError("mean curvature measure: vertex " + std::to_string(v) +
                         " has a non-finite position or reference point");
    if (tri_.background != intrinsic::Background::Euclidean)
      throw InputError("mean curvature measure: the mesh must be Euclidean (a mesh in R³), found " +
                       intrinsic::toString(tri_.background));
    const std::string problem = options_.validate();
    if (!problem.empty()) throw InputError(problem);
  }

  // Area, β(e) and |e| of the mesh, Σ |e| β(e), and the ball radius.
  void measureMesh() {
    double area = 0;
    for (int f = 0; f < nF_; ++f) {
      const auto& a = positions_[mesh_.faceVertex(f, 0)];
      const auto& b = positions_[mesh_.faceVertex(f, 1)];
      const auto& c = positions_[mesh_.faceVertex(f, 2)];
      area += 0.5 * (b - a).cross(c - a).norm();
    }
    beta_.resize(nE_), length_.resize(nE_);
    for (int e = 0; e < nE_; ++e) {
      const int h = mesh_.edgeHalfedge(e);
      beta_[e] = signedDihedralAngle(mesh_, positions_, e);
      length_[e] = (positions_[mesh_.tip(h)] - positions_[mesh_.tail(h)]).norm();
      longest_ = std::max(longest_, length_[e]);
      r_.discreteTotal += length_[e] * beta_[e];
    }
    r_.radius = options_.radiusFraction * std::sqrt(area);
  }

  // Grid point (i, j), i + j ≤ n, of a triangle is its barycentric place (1 − (i+j)/n, i/n, j/n).
  int gridIndex(int i, int j) const { return j * (n_ + 1) - j * (j - 1) / 2 + i; }

  // Sub-triangles as grid-point triples: "up" (i,j),(i+1,j),(i,j+1) and "down" (i+1,j),(i+1,j+1),(i,j+1).
  void buildSubTriangles() {
    n_ = 1 << options_.subdivision;
    gridPoints_ = (n_ + 1) * (n_ + 2) / 2, subTriangles_ = n_ * n_;
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i + j < n_; ++i) {
        sub_.push_back({Eigen::Vector2i(i, j), Eigen::Vector2i(i + 1, j), Eigen::Vector2i(i, j + 1)});
        if (i + j + 1 < n_)
          sub_.push_back({Eigen::Vector2i(i + 1, j), Eigen::Vector2i(i + 1, j + 1), Eigen::Vector2i(i, j + 1)});
      }
    subArea_ = 0.5 / (n_ * n_);  // (s, t)-area of a sub-triangle
  }

  // Per face: the surface at its grid points; per sub-triangle k and edge m (from corner m to corner m+1): the surface
  // point at the edge midpoint and the densities (κ₁ + κ₂)·|X_s × X_t| and |κ₁ + κ₂|·|X_s × X_t| there. Adds the
  // degree-2 rule's total to smoothTotal.
  void preintegrateSurface() {
    gridPos_.resize(static_cast<std::size_t>(nF_) * gridPoints_);
    const std::size_t nodes = static_cast<std::size_t>(nF_) * subTriangles_ * 3;
    midPos_.resize(nodes), midH_.resize(nodes), midAbsH_.resize(nodes);
    for (int f = 0; f < nF_; ++f) {
      const Eigen::Vector3d& ya = referencePoints_[mesh_.faceVertex(f, 0)];
      const Eigen::Vector3d e1 = referencePoints_[mesh_.faceVertex(f, 1)] - ya;
      const Eigen::Vector3d e2 = referencePoints_[mesh_.faceVertex(f, 2)] - ya;
      for (int j = 0; j <= n_; ++j)
        for (int i = 0; i + j <= n_; ++i)
          gridPos_[static_cast<std::size_t>(f) * gridPoints_ + gridIndex(i, j)] =
              surface_.position(ya + (double(i) / n_) * e1 + (double(j) / n_) * e2);
      for (int k = 0; k < subTriangles_; ++k) preintegrateSubTriangle(f, k, ya, e1, e2);
    }
  }

  // The density is (κ₁ + κ₂)·|X_s × X_t| for X(s, t) = position(ya + s e₁ + t e₂), whose normal X_s × X_t has the
  // triangle's orientation — the orientation the signs of β(e) refer to.
  void preintegrateSubTriangle(int f, int k, const Eigen::Vector3d& ya, const Eigen::Vector3d& e1,
                               const Eigen::Vector3d& e2) {
    double sum = 0;
    for (int m = 0; m < 3; ++m) {
      const Eigen::Vector2d st = (sub_[k][m] + sub_[k][(m + 1) % 3]).cast<double>() / (2.0 * n_);
      const LocalSurfaceJet jet = surface_.jet(ya + st.x() * e1 + st.y() * e2, e1, e2, true);
      const std::size_t id = (static_cast<std::size_t>(f) * subTriangles_ + k) * 3 + m;
      midPos_[id] = jet.position;
      midH_[id] = jet.meanCurvature * jet.areaFactor;
      midAbsH_[id] = std::abs(jet.meanCurvature) * jet.areaFactor;
      sum += midH_[id];
    }
    // Degree-2 rule: area/3 × Σ of the density at the three edge midpoints.
    r_.smoothTotal += sum * subArea_ / 3;
  }

  // Adds ∫ (κ₁ + κ₂) dA and ∫ |κ₁ + κ₂| dA over the part of sub-triangle k of face f inside B(c, r).
  void subIntegral(int f, int k, const Eigen::Vector3d& c, double& valueH, double& valueAbsH) const {
    const std::size_t base = (static_cast<std::size_t>(f) * subTriangles_ + k) * 3;
    std::array<double, 3> phiC, phiM;
    int negative = 0;
    for (int m = 0; m < 3; ++m) {
      phiC[m] =
          (gridPos_[static_cast<std::size_t>(f) * gridPoints_ + gridIndex(sub_[k][m].x(), sub_[k][m].y())] - c).norm() -
          r_.radius;
      phiM[m] = (midPos_[base + m] - c).norm() - r_.radius;
      negative += (phiC[m] < 0) + (phiM[m] < 0);
    }
    if (negative == 0) return;
    if (negative == 6) {
      valueH += subArea_ * (midH_[base] + midH_[base + 1] + midH_[base + 2]) / 3;
      valueAbsH += subArea_ * (midAbsH_[base] + midAbsH_[base + 1] + midAbsH_[base + 2]) / 3;
      return;
    }
    clipSubTriangle(base, phiC, phiM, valueH, valueAbsH);
  }

  // The cut sub-triangle: kMini² pieces, each clipped by the linear interpolant of the P2 level function at its
  // corners, with the linear density through the midpoint values at its centroid.
  void clipSubTriangle(std::size_t base, const std::array<double, 3>& phiC, const std::array<double, 3>& phiM,
                       double& valueH, double& valueAbsH) const {
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
    const double miniArea = subArea_ / (kMini * kMini);
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
          valueH += share * miniArea * densityAt(centroid, midH_);
          valueAbsH += share * miniArea * densityAt(centroid, midAbsH_);
        }
  }

  // Per-vertex balls. A triangle or edge meeting B(v, r) has all its corners within r + (longest edge) of v; the
  // images of triangles are within O(ε²) of them, far inside that margin.
  void measureBalls() {
    const double reach = r_.radius + longest_;
    VertexGrid grid(positions_, reach);
    faceStamp_.assign(nF_, -1), edgeStamp_.assign(nE_, -1);
    r_.discrete.assign(nV_, 0);
    r_.smooth.assign(nV_, 0);
    r_.absoluteScale.assign(nV_, 0);
    r_.relativeError.assign(nV_, 0);
    for (int v = 0; v < nV_; ++v) {
      const Eigen::Vector3d c = positions_[v];
      double discrete = 0, smooth = 0, scale = 0;
      grid.forEachWithin(c, reach, [&](int w) {
        const int start = mesh_.vertexHalfedge(w);
        int h = start;
        do {
          const int f = HalfedgeMesh::face(h);
          if (faceStamp_[f] != v) {
            faceStamp_[f] = v;
            addFace(v, f, c, discrete, smooth, scale);
          }
          h = mesh_.nextOutgoing(h);
        } while (h != kInvalid && h != start);
      });
      r_.discrete[v] = discrete;
      r_.smooth[v] = smooth;
      r_.absoluteScale[v] = scale;
      r_.relativeError[v] = scale > 0 ? (discrete - smooth) / scale : 0.0;
    }
  }

  // Face f's part of ball v: its edges not yet counted for v (eq. 2), then its sub-triangles.
  void addFace(int v, int f, const Eigen::Vector3d& c, double& discrete, double& smooth, double& scale) {
    for (int k = 0; k < 3; ++k) {
      const int hk = HalfedgeMesh::halfedge(f, k), e = mesh_.edge(hk);
      if (edgeStamp_[e] == v) continue;
      edgeStamp_[e] = v;
      if (beta_[e] != 0)
        discrete += beta_[e] * segmentLengthInBall(positions_[mesh_.tail(hk)], positions_[mesh_.tip(hk)], c, r_.radius);
    }
    for (int k = 0; k < subTriangles_; ++k) subIntegral(f, k, c, smooth, scale);
  }

  void summarize() {
    r_.histogram.assign(options_.histogramBins, 0);
    int within = 0;
    double sumAbs = 0, sumRel = 0;
    for (int v = 0; v < nV_; ++v) {
      const double err = std::abs(r_.discrete[v] - r_.smooth[v]);
      sumAbs += err;
      r_.maxAbsoluteError = std::max(r_.maxAbsoluteError, err);
      const double rel = r_.relativeError[v];
      sumRel += std::abs(rel);
      within += std::abs(rel) < options_.withinBand;
      const double t = (rel + options_.histogramRange) / (2 * options_.histogramRange);
      const int bin =
          std::clamp(static_cast<int>(std::floor(t * options_.histogramBins)), 0, options_.histogramBins - 1);
      ++r_.histogram[bin];
    }
    r_.meanAbsoluteError = sumAbs / nV_;
    r_.meanRelativeError = sumRel / nV_;
    r_.fractionWithinBand = static_cast<double>(within) / nV_;
  }

  const HalfedgeMesh& mesh_;
  const intrinsic::IntrinsicTriangulation& tri_;
  const std::vector<Eigen::Vector3d>& positions_;
  const std::vector<Eigen::Vector3d>& referencePoints_;
  const EmbeddedSurface& surface_;
  const MeanCurvatureMeasureOptions& options_;
  const int nV_, nF_, nE_;
  MeanCurvatureMeasureResult r_;
  std::vector<double> beta_, length_;
  double longest_ = 0;
  int n_ = 1, gridPoints_ = 0, subTriangles_ = 0;
  double subArea_ = 0;
  std::vector<std::array<Eigen::Vector2i, 3>> sub_;
  std::vector<Eigen::Vector3d> gridPos_, midPos_;
  std::vector<double> midH_, midAbsH_;
  std::vector<int> faceStamp_, edgeStamp_;
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

std::string MeanCurvatureMeasureOptions::validate() const {
  if (subdivision < 0 || subdivision > 6)
    return "mean curvature measure: subdivision must be in 0..6, found " + std::to_string(subdivision);
  if (!(radiusFraction > 0) || histogramBins < 1 || !(histogramRange > 0))
    return "mean curvature measure: radius fraction and histogram range must be positive, bins ≥ 1";
  return "";
}

MeanCurvatureMeasureResult meanCurvatureMeasure(const intrinsic::IntrinsicTriangulation& tri,
                                                const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const EmbeddedSurface& surface,
                                                const MeanCurvatureMeasureOptions& options) {
  return MeanCurvatureMeasure(tri, positions, referencePoints, surface, options).run();
}

}  // namespace conformesh::embedding
