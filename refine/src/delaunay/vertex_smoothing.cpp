// vertex_smoothing.cpp — the smoothing pass of vertex_smoothing.h: per free vertex a start (ODT point or centroid
// average) in its star's layout, a compass search on the star's score, and the move by relocateVertex.
#include "conformesh/refine/delaunay/vertex_smoothing.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/trace/robust_predicates.h"
#include "conformesh/refine/delaunay/vertex_relocation.h"

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

std::string toString(SmoothingRule rule) {
  return rule == SmoothingRule::Centroid ? "centroid" : "odt";
}

SmoothingRule parseSmoothingRule(const std::string& name) {
  if (name == "odt") return SmoothingRule::OptimalDelaunay;
  if (name == "centroid") return SmoothingRule::Centroid;
  throw InputError("smoothing rule '" + name + "' is not one of: odt, centroid");
}

namespace {

// The target of v in its star layout: Σ A_i x_i / Σ A_i over the star triangles (O, U_i, U_{i+1}), x_i the
// circumcentre (ODT) or the centroid. Sums of model vectors rescaled onto the model are the projective (gnomonic /
// Klein) weighted means, exact in the plane and a second-order approximation of the Riemannian mean for small stars,
// which is all a smoothing target needs.
Vec3 smoothingTarget(const IntrinsicTriangulation& tri, const BackgroundModel& model, const VertexStar& star,
                     SmoothingRule rule) {
  const Vec3 O = BackgroundModel::origin();
  const int d = static_cast<int>(star.out.size());
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < d; ++i) {
    const Vec3 &a = star.ring[i], &b = star.ring[(i + 1) % d];
    const double area = intrinsic::triangleArea(tri.background, tri.length(HalfedgeMesh::next(star.out[i])),
                                                tri.length(star.out[i]), tri.length(star.out[(i + 1) % d]));
    Vec3 x = model.normalize(O + a + b);
    if (rule == SmoothingRule::OptimalDelaunay)
      if (const std::optional<Vec3> c = model.circumcenter(O, a, b)) x = *c;
    sum += area * x;
  }
  return model.normalize(sum);
}

// The smallest angle (the one opposite the shortest side, in every constant-curvature geometry) and the circumradius
// of the counter-clockwise triangle (P, A, B) with sides o = |AB|, a = |PA|, b = |PB|; false when the sides violate
// the strict triangle inequality. Euclidean: one Kahan–Heron area serves both, angle = atan2(4·area, x² + y² − s²) and
// R = abc / (4·area). Curved: from the model vectors (the angle between two tangents, the circumcentre of
// BackgroundModel, +∞ for a hyperbolic triangle without circumcircle), a few products instead of the half-perimeter
// sines of the length formulas — this is the inner loop of the search.
// With wantAngle = false only R is computed (the graded score measures angles in another metric).
bool smallestAngleAndCircumradius(const BackgroundModel& model, const Vec3& P, const Vec3& A, const Vec3& B, double o,
                                  double a, double b, bool wantAngle, double& angle, double& R) {
  const Background g = model.background();
  if (!intrinsic::isValidTriangle(g, o, a, b)) return false;
  if (g == Background::Euclidean) {
    double s = o, x = a, y = b;
    if (x < s) std::swap(s, x);
    if (y < s) std::swap(s, y);
    const double area4 = detail::fourAreaEuclidean(o, a, b);
    if (!(area4 > 0)) return false;
    angle = std::atan2(area4, x * x + y * y - s * s);
    R = o * a * b / area4;
    return true;
  }
  if (wantAngle) {
    const Vec3 *X = &P, *Y = &A, *Z = &B;  // X: the corner opposite the shortest side
    if (a < o && a <= b)
      X = &B, Y = &P, Z = &A;
    else if (b < o && b < a)
      X = &A, Y = &P, Z = &B;
    const Vec3 tY = model.tangentToward(*X, *Y), tZ = model.tangentToward(*X, *Z);
    angle = std::atan2(std::abs(model.inner(tZ, model.turnLeft(*X, tY))), model.inner(tY, tZ));
  }
  const std::optional<Vec3> c = model.circumcenter(P, A, B);
  R = c ? model.distance(*c, P) : INFINITY;
  return true;
}

// Smallest angle of the flat triangle with sides a, b, c (opposite the shortest side); 0 when degenerate.
double euclideanSmallestAngle(double a, double b, double c) {
  double s = a, x = b, y = c;
  if (x < s) std::swap(s, x);
  if (y < s) std::swap(s, y);
  return std::atan2(detail::fourAreaEuclidean(a, b, c), x * x + y * y - s * s);
}

}  // namespace

SmoothingStatistics smoothFreeVertices(IntrinsicTriangulation& tri, Signposts& sp,
                                       std::vector<InputLocation>& locations, std::vector<double>& lambda,
                                       int inputVertices, const InputSurface& input,
                                       const std::vector<double>& inputLambda, const SmoothingOptions& options) {
  const HalfedgeMesh& m = tri.mesh;
  const BackgroundModel model(tri.background);
  const Background g = tri.background;
  SmoothingStatistics stats;
  std::vector<double> dist, halfExp;
  for (int v = inputVertices; v < m.nVertices(); ++v) {
    const std::optional<VertexStar> star = layoutStar(tri, sp, v, inputVertices);
    if (!star) continue;
    ++stats.candidates;
    const int d = static_cast<int>(star->out.size());
    // Graded (λ given): angles are taken in the metric e^(2λ)·background the mesh is measured in after the pull-back
    // — flat triangles with lengths ℓ·e^((λ_i + λ_j)/2), the trapezoidal rule for ∫e^λ ds, second-order accurate —
    // with λ(p) from the least-squares linear fit λ ≈ c0 + c1·x + c2·y over v and its neighbours in the star's chart.
    // Without λ, the background's own angles.
    const bool graded = !inputLambda.empty();
    Eigen::Vector3d fit(0, 0, 0);
    halfExp.resize(d);
    if (graded) {
      Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
      Eigen::Vector3d Atb = Eigen::Vector3d::Zero();
      auto add = [&](double x, double y, double l) {
        const Eigen::Vector3d r(1, x, y);
        AtA += r * r.transpose();
        Atb += l * r;
      };
      add(0, 0, lambda[v]);
      for (int i = 0; i < d; ++i) {
        const Vec3& u = star->ring[i];
        add(u.x() / u.z(), u.y() / u.z(), lambda[m.tip(star->out[i])]);
        halfExp[i] = std::exp(lambda[m.tip(star->out[i])] / 2);
      }
      fit = AtA.ldlt().solve(Atb);
      if (!fit.allFinite()) fit = Eigen::Vector3d(lambda[v], 0, 0);
    }
    // Smallest angle of star triangle i with spokes a = |p u_i|, b = |p u_{i+1}|; bgAngle: the background's.
    auto measured = [&](int i, double a, double b, double epv, double bgAngle) {
      if (!graded) return bgAngle;
      const int j = (i + 1) % d;
      const double o = tri.length(HalfedgeMesh::next(star->out[i])) * halfExp[i] * halfExp[j];
      return euclideanSmallestAngle(o, a * epv * halfExp[i], b * epv * halfExp[j]);
    };
    // The star's smallest angle and the sum of its triangles' smallest angles (their share of the mean smallest angle
    // of the mesh: moving v changes no other triangle).
    double oldMin = INFINITY, oldSum = 0;
    for (int i = 0; i < d; ++i) {
      const int h = star->out[i];
      double t = std::min({fastCornerAngle(tri, h), fastCornerAngle(tri, HalfedgeMesh::next(h)),
                           fastCornerAngle(tri, HalfedgeMesh::prev(h))});
      t = measured(i, tri.length(h), tri.length(star->out[(i + 1) % d]), std::exp(fit[0] / 2), t);
      oldMin = std::min(oldMin, t);
      oldSum += t;
    }
    // The score of position p: the sum of the per-triangle smallest angles of the moved star, or −∞ when the star
    // folds, its smallest angle decreases, or a triangle breaks a bound.
    // The same validity test as isValidStarPosition (exact orientation, triangle inequality), fused with the shape
    // evaluation: this runs some tens of times per vertex.
    auto score = [&](const Vec3& p) -> double {
      if (!p.allFinite() || (g == Background::Spherical && !(p.z() > 0))) return -INFINITY;
      dist.resize(d);
      for (int i = 0; i < d; ++i) dist[i] = model.distance(p, star->ring[i]);
      const double lambdaP = graded ? fit[0] + fit[1] * p.x() / p.z() + fit[2] * p.y() / p.z() : 0.0;
      const double epv = std::exp(lambdaP / 2);
      double sum = 0;
      for (int i = 0; i < d; ++i) {
        const int j = (i + 1) % d, outerH = HalfedgeMesh::next(star->out[i]);
        if (orientationSign(p, star->ring[i], star->ring[j]) <= 0) return -INFINITY;
        const double o = tri.length(outerH), a = dist[i], b = dist[j];
        double tMin = 0, R = 0;
        if (!smallestAngleAndCircumradius(model, p, star->ring[i], star->ring[j], o, a, b, !graded, tMin, R))
          return -INFINITY;
        tMin = measured(i, a, b, epv, tMin);
        // The smallest angle of the star may not decrease (ties allowed).
        if (tMin < oldMin) return -INFINITY;
        // Strict comparisons with the refinement's relative slack 1e-12 (processFace): a triangle at a bound is good.
        if (!(R <= options.ratioBound * std::min({o, a, b}) * (1 + 1e-12))) return -INFINITY;
        if (std::isfinite(options.epsilon)) {
          double lam = 0;
          if (graded) lam = (lambdaP + lambda[m.tip(star->out[i])] + lambda[m.tip(star->out[j])]) / 3;
          if (!(R * std::exp(lam) <= options.epsilon * (1 + 1e-12))) return -INFINITY;
        }
        // A boundary edge of the star stays unencroached: its apex angle (at p) at most 90° (Ruppert's test, with the
        // refinement's 1e-10 rad slack).
        if (m.twin(outerH) == kInvalid && intrinsic::angleOpposite(g, o, a, b) > M_PI / 2 + 1e-10) return -INFINITY;
        sum += tMin;
      }
      return sum;
    };
    // The rule's target and the points halfway and a quarter of the way to it (the projective segment O → target is
    // the geodesic in every model).
    const Vec3 target = smoothingTarget(tri, model, *star, options.rule);
    double best = oldSum;
    Vec3 bestP = BackgroundModel::origin();
    bool anyValid = false, moved = false;
    for (int attempt = 0; attempt < 3; ++attempt) {
      const double t = std::ldexp(1.0, -attempt);
      const Vec3 p = attempt == 0 ? target : model.normalize((1 - t) * BackgroundModel::origin() + t * target);
      if (isValidStarPosition(tri, *star, p)) anyValid = true;
      const double sc = score(p);
      if (sc > best) best = sc, bestP = p;
    }
    // Then a compass search on the score around the best point so far (8 directions; the step starts at 1/8 of the
    // distance to the nearest neighbour and is halved 3 times when no direction improves; at most 64 rounds): the
    // rule's target is a good start, the score is what the acceptance asks for. Measured on the Kerr a/M = 0.99 sweep
    // (2k vertices, 3 passes, background-metric scores): ODT target alone 46.49°, with the search 46.83°; starting at
    // 1/4 with 4 halvings (same finest step) gives the same mean, 3 halvings from 1/4 lose 0.15°. Steps are taken
    // in the straight-line chart (x/z, y/z) of the model, which is isometric to first order at the star's centre: the
    // search needs a pattern of nearby points, not exact distances, and the chart spares the exponential map.
    {
      static const double kCos[8] = {1, M_SQRT1_2, 0, -M_SQRT1_2, -1, -M_SQRT1_2, 0, M_SQRT1_2};
      static const double kSin[8] = {0, M_SQRT1_2, 1, M_SQRT1_2, 0, -M_SQRT1_2, -1, -M_SQRT1_2};
      double nearest = INFINITY;
      for (int i = 0; i < d; ++i) nearest = std::min(nearest, tri.length(star->out[i]));
      double step = 0.125 * nearest;
      for (int halvings = 0, iterations = 0; halvings < 3 && iterations < 64; ++iterations) {
        bool improved = false;
        for (int k = 0; k < 8; ++k) {
          const Vec3 q = model.normalize(
              Vec3(bestP.x() / bestP.z() + step * kCos[k], bestP.y() / bestP.z() + step * kSin[k], 1.0));
          const double sc = score(q);
          if (sc > best) best = sc, bestP = q, improved = true;
        }
        if (!improved) step /= 2, ++halvings;
      }
    }
    // 1e-12 rad: a gain at the round-off level of the angle sums is no gain (it would move vertices on every pass).
    if (best > oldSum + 1e-12 && relocateVertex(tri, sp, locations, input, *star, bestP)) {
      moved = true;
      if (!inputLambda.empty()) lambda[v] = input.interpolate(inputLambda, locations[v]);
    }
    if (moved)
      ++stats.moved;
    else if (!anyValid)
      ++stats.invalid;
    else
      ++stats.rejected;
  }
  return stats;
}

}  // namespace conformesh::refine
