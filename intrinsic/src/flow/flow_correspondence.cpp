// flow_correspondence.cpp — mapping points between T0* and T0 through the decoration change e^{w/2} and the Ptolemy
// flip log, in the decorated-ideal (light-cone) model. See flow_correspondence.h and docs/ricci_flow.md.
#include "conformesh/intrinsic/flow/flow_correspondence.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

// Coefficients (α, β, γ) with p_d = α p_a + β p_b + γ p_c for the light-like vectors of an ideal quad,
// <p_i, p_j> = −c_ij²/2. Solves the 3×3 Gram system G_abc (α, β, γ)ᵀ = (<p_d,p_a>, <p_d,p_b>, <p_d,p_c>) with the
// closed-form inverse of [[0,x,y],[x,0,z],[y,z,0]]: 1/(2xyz) [[−z², yz, xz], [yz, −y², xy], [xz, xy, −x²]]
// (x = G_ab, y = G_ac, z = G_bc).
void quadRelation(const PtolemyFlip& q, double& alpha, double& beta, double& gamma) {
  // The relation is computed in the decoration c'_ij = e^{(s_i+s_j)/2} c_ij, i.e. p'_i = e^{s_i} p_i, that makes
  // c'_ab = c'_bc = c'_ca = 1 and c'_ad c'_db = 1: after many flips far from the solution the reference lengths of
  // one quad can differ by 10⁹, and the Gram solve below would cancel catastrophically; in the balanced decoration it
  // is well conditioned. Then α = α' e^{s_a − s_d} etc. (products only, no cancellation).
  const double ea = std::sqrt(q.bc / (q.ab * q.ca)), eb = std::sqrt(q.ca / (q.ab * q.bc)),
               ec = std::sqrt(q.ab / (q.bc * q.ca));  // e^{s/2}
  const double ed = 1 / std::sqrt(q.ad * ea * q.db * eb);
  const double ad = q.ad * ea * ed, db = q.db * eb * ed, cd = q.cd * ec * ed;
  const double x = -0.5, y = -0.5, z = -0.5;  // −c'²/2 for ab, ca, bc
  const double ra = -0.5 * ad * ad, rb = -0.5 * db * db, rc = -0.5 * cd * cd;
  const double s = 1.0 / (2 * x * y * z);
  alpha = s * (-z * z * ra + y * z * rb + x * z * rc) * (ea / ed) * (ea / ed);
  beta = s * (y * z * ra - y * y * rb + x * y * rc) * (eb / ed) * (eb / ed);
  gamma = s * (x * z * ra + x * y * rb - x * x * rc) * (ec / ed) * (ec / ed);
}

// Normalizes projective coefficients to barycentric ones (sum 1), clamping round-off negatives.
std::array<double, 3> normalized(double p, double q, double r) {
  p = std::max(p, 0.0);
  q = std::max(q, 0.0);
  r = std::max(r, 0.0);
  const double s = p + q + r;
  return {p / s, q / s, r / s};
}

std::string lostPrecision(std::ptrdiff_t flip) {
  return "flow correspondence: flip " + std::to_string(flip) +
         " of the log re-expresses a point with no positive coordinates; its quad's Penner lengths are too disparate "
         "for double precision (the flow passed through an extreme conformal factor)";
}

void validate(const std::vector<FacePoint>& points, int nFaces) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const FacePoint& p = points[i];
    const double s = p.bary[0] + p.bary[1] + p.bary[2];
    const bool finite = std::isfinite(p.bary[0]) && std::isfinite(p.bary[1]) && std::isfinite(p.bary[2]);
    if (p.face < 0 || p.face >= nFaces || !finite || std::min({p.bary[0], p.bary[1], p.bary[2]}) < -1e-9 ||
        std::abs(s - 1) > 1e-9) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "flow correspondence: point " << i << " (face " << p.face << ", barycentric " << p.bary[0] << ", "
          << p.bary[1] << ", " << p.bary[2] << ") is not a point of a face 0.." << nFaces - 1;
      throw InputError(msg.str());
    }
  }
}

// Per-face buckets of point indices (CSR would need a rebuild per flip; vectors keep moves O(1) amortized).
struct Buckets {
  std::vector<std::vector<int>> of;
  explicit Buckets(int nFaces, const std::vector<FacePoint>& pts) : of(nFaces) {
    for (std::size_t i = 0; i < pts.size(); ++i) of[pts[i].face].push_back(static_cast<int>(i));
  }
  // Moves the points of the flip's two faces into `moving` (they are about to change faces).
  void take(const PtolemyFlip& q, std::vector<int>& moving) {
    moving.clear();
    moving.insert(moving.end(), of[q.faceA].begin(), of[q.faceA].end());
    moving.insert(moving.end(), of[q.faceB].begin(), of[q.faceB].end());
    of[q.faceA].clear();
    of[q.faceB].clear();
  }
};

// Rescales barycentric coordinates between decorations: c_ij = e^{(w_i+w_j)/2} c⁰_ij means p_i = e^{w_i} p⁰_i
// (<p_i, p_j> = −c_ij²/2), so b_i ∝ b_i e^{sign·w_i}.
void rescale(const HalfedgeMesh& mesh, const std::vector<double>& w, double sign, std::vector<FacePoint>& pts) {
  if (w.empty()) return;
  for (FacePoint& p : pts) {
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = p.bary[k] * std::exp(sign * w[mesh.faceVertex(p.face, k)]);
    p.bary = normalized(q[0], q[1], q[2]);
  }
}

}  // namespace

std::vector<FacePoint> FlowCorrespondence::mapToInput(const HalfedgeMesh& uniformMesh,
                                                      const std::vector<FacePoint>& pointsOnUniform) const {
  validate(pointsOnUniform, nFaces_);
  std::vector<FacePoint> pts = pointsOnUniform;
  // T0* decoration → reference decoration: the ray Σ b_i p_i(w) = Σ b_i e^{w_i} p_i(0).
  rescale(uniformMesh, logScale, +1.0, pts);
  Buckets buckets(nFaces_, pts);
  std::vector<int> moving;
  for (auto it = flips_.rbegin(); it != flips_.rend(); ++it) {
    const PtolemyFlip& q = *it;
    if (buckets.of[q.faceA].empty() && buckets.of[q.faceB].empty()) continue;
    double alpha, beta, gamma;
    quadRelation(q, alpha, beta, gamma);
    buckets.take(q, moving);
    for (int i : moving) {
      FacePoint& p = pts[i];
      // Post-flip coefficients on p_a, p_b, p_c, p_d: fa = (d, c, a), fb = (c, d, b).
      double Ka = 0, Kb = 0, Kc, Kd;
      if (p.face == q.faceA) {
        Kd = p.bary[0];
        Kc = p.bary[1];
        Ka = p.bary[2];
      } else {
        Kc = p.bary[0];
        Kd = p.bary[1];
        Kb = p.bary[2];
      }
      // In (a, b, c): eliminate p_d. In (b, a, d): eliminate p_c = (p_d − α p_a − β p_b)/γ.
      const double A1 = Ka + Kd * alpha, B1 = Kb + Kd * beta, C1 = Kc + Kd * gamma;
      const double A2 = Ka - Kc * alpha / gamma, B2 = Kb - Kc * beta / gamma, D2 = Kd + Kc / gamma;
      // The point lies in the triangle where its coefficients are all non-negative; round-off decides by the smaller
      // relative violation.
      const double m1 = std::min({A1, B1, C1}) / (std::abs(A1) + std::abs(B1) + std::abs(C1));
      const double m2 = std::min({A2, B2, D2}) / (std::abs(A2) + std::abs(B2) + std::abs(D2));
      const bool ok1 = std::isfinite(m1) && std::max({A1, B1, C1}) > 0,
                 ok2 = std::isfinite(m2) && std::max({A2, B2, D2}) > 0;
      if (!ok1 && !ok2) throw ConvergenceError(lostPrecision(flips_.rend() - it - 1));
      if (ok1 && (m1 >= m2 || !ok2)) {
        const std::array<double, 3> abc = normalized(A1, B1, C1);
        p.face = q.faceA;
        p.bary[q.cornerA] = abc[0];
        p.bary[(q.cornerA + 1) % 3] = abc[1];
        p.bary[(q.cornerA + 2) % 3] = abc[2];
      } else {
        const std::array<double, 3> bad = normalized(B2, A2, D2);
        p.face = q.faceB;
        p.bary[q.cornerB] = bad[0];
        p.bary[(q.cornerB + 1) % 3] = bad[1];
        p.bary[(q.cornerB + 2) % 3] = bad[2];
      }
      buckets.of[p.face].push_back(i);
    }
  }
  return pts;
}

std::vector<FacePoint> FlowCorrespondence::mapToUniform(const HalfedgeMesh& uniformMesh,
                                                        const std::vector<FacePoint>& pointsOnInput) const {
  validate(pointsOnInput, nFaces_);
  std::vector<FacePoint> pts = pointsOnInput;
  Buckets buckets(nFaces_, pts);
  std::vector<int> moving;
  for (const PtolemyFlip& q : flips_) {
    if (buckets.of[q.faceA].empty() && buckets.of[q.faceB].empty()) continue;
    // Forwards, a point of (a, b, c) or (b, a, d) is re-expressed in the post-flip triangles (d, c, a) or (c, d, b)
    // by eliminating p_b or p_a from the same linear relation of the quad.
    double alpha, beta, gamma;
    quadRelation(q, alpha, beta, gamma);
    buckets.take(q, moving);
    for (int i : moving) {
      FacePoint& p = pts[i];
      double Ka = 0, Kb = 0, Kc = 0, Kd = 0;
      if (p.face == q.faceA) {
        Ka = p.bary[q.cornerA];
        Kb = p.bary[(q.cornerA + 1) % 3];
        Kc = p.bary[(q.cornerA + 2) % 3];
      } else {
        Kb = p.bary[q.cornerB];
        Ka = p.bary[(q.cornerB + 1) % 3];
        Kd = p.bary[(q.cornerB + 2) % 3];
      }
      // Relation α p_a + β p_b + γ p_c − p_d = 0. Eliminate p_b: p_b = (p_d − α p_a − γ p_c)/β; eliminate p_a:
      // p_a = (p_d − β p_b − γ p_c)/α.
      const double A1 = Ka - Kb * alpha / beta, C1 = Kc - Kb * gamma / beta, D1 = Kd + Kb / beta;    // in (d, c, a)
      const double B2 = Kb - Ka * beta / alpha, C2 = Kc - Ka * gamma / alpha, D2 = Kd + Ka / alpha;  // in (c, d, b)
      const double m1 = std::min({A1, C1, D1}) / (std::abs(A1) + std::abs(C1) + std::abs(D1));
      const double m2 = std::min({B2, C2, D2}) / (std::abs(B2) + std::abs(C2) + std::abs(D2));
      const bool ok1 = std::isfinite(m1) && std::max({A1, C1, D1}) > 0,
                 ok2 = std::isfinite(m2) && std::max({B2, C2, D2}) > 0;
      if (!ok1 && !ok2) throw ConvergenceError(lostPrecision(&q - flips_.data()));
      if (ok1 && (m1 >= m2 || !ok2)) {
        p.face = q.faceA;
        p.bary = normalized(D1, C1, A1);
      } else {
        p.face = q.faceB;
        p.bary = normalized(C2, D2, B2);
      }
      buckets.of[p.face].push_back(i);
    }
  }
  rescale(uniformMesh, logScale, -1.0, pts);
  return pts;
}

}  // namespace conformesh::intrinsic
