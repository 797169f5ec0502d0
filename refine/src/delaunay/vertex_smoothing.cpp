// vertex_smoothing.cpp — the smoothing pass of vertex_smoothing.h: per free vertex a start (ODT point or centroid
// average) in its star's layout, a compass search on the star's score, and the move by relocateVertex.
#include "conformesh/refine/delaunay/vertex_smoothing.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/Cholesky>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/delaunay/vertex_relocation.h"
#include "conformesh/refine/trace/robust_predicates.h"

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

// One smoothing pass (smoothFreeVertices): per free vertex, its star's current score, the candidates from the rule's
// target, a compass search, and the move. Per-vertex state lives in members, reset by smoothVertex; the distance
// buffer is reused from vertex to vertex.
class StarSmoother {
 public:
  StarSmoother(IntrinsicTriangulation& tri, Signposts& sp, std::vector<InputLocation>& locations,
               std::vector<double>& lambda, const InputSurface& input, const std::vector<double>& inputLambda,
               const SmoothingOptions& options)
      : tri_(tri),
        m_(tri.mesh),
        sp_(sp),
        locations_(locations),
        lambda_(lambda),
        input_(input),
        inputLambda_(inputLambda),
        options_(options),
        model_(tri.background),
        g_(tri.background) {}

  // Smooths vertex v, counting the outcome in `stats`.
  void smoothVertex(int v, int inputVertices, SmoothingStatistics& stats);

 private:
  void fitLambda(int v);
  double measured(int i, double a, double b, double epv, double bgAngle) const;
  void measureStar();
  double score(const Vec3& p);
  bool tryStartingPoints();
  void compassSearch();

  IntrinsicTriangulation& tri_;
  const HalfedgeMesh& m_;
  Signposts& sp_;
  std::vector<InputLocation>& locations_;
  std::vector<double>& lambda_;
  const InputSurface& input_;
  const std::vector<double>& inputLambda_;
  const SmoothingOptions& options_;
  const BackgroundModel model_;
  const Background g_;
  std::vector<double> dist_, halfExp_;
  // === the current vertex
  std::optional<VertexStar> star_;
  int d_ = 0;                       // its degree
  bool graded_ = false;             // λ given: angles in the metric e^(2λ)·background
  Eigen::Vector3d fit_;             // λ ≈ fit0 + fit1·x + fit2·y in the star's chart
  double oldMin_ = 0, oldSum_ = 0;  // the star's smallest angle and sum of per-triangle smallest angles
  double best_ = 0;                 // the best score so far, at bestP_
  Vec3 bestP_;
};

void StarSmoother::smoothVertex(int v, int inputVertices, SmoothingStatistics& stats) {
  star_ = layoutStar(tri_, sp_, v, inputVertices);
  if (!star_) return;
  ++stats.candidates;
  d_ = static_cast<int>(star_->out.size());
  fitLambda(v);
  measureStar();
  const bool anyValid = tryStartingPoints();
  compassSearch();
  bool moved = false;
  // 1e-12 rad: a gain at the round-off level of the angle sums is no gain (it would move vertices on every pass).
  if (best_ > oldSum_ + 1e-12 && relocateVertex(tri_, sp_, locations_, input_, *star_, bestP_)) {
    moved = true;
    if (!inputLambda_.empty()) lambda_[v] = input_.interpolate(inputLambda_, locations_[v]);
  }
  if (moved)
    ++stats.moved;
  else if (!anyValid)
    ++stats.invalid;
  else
    ++stats.rejected;
}

void StarSmoother::fitLambda(int v) {
  // Graded (λ given): angles are taken in the metric e^(2λ)·background the mesh is measured in after the pull-back
  // — flat triangles with lengths ℓ·e^((λ_i + λ_j)/2), the trapezoidal rule for ∫e^λ ds, second-order accurate —
  // with λ(p) from the least-squares linear fit λ ≈ c0 + c1·x + c2·y over v and its neighbours in the star's chart.
  // Without λ, the background's own angles.
  graded_ = !inputLambda_.empty();
  fit_ = Eigen::Vector3d(0, 0, 0);
  halfExp_.resize(d_);
  if (!graded_) return;
  Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
  Eigen::Vector3d Atb = Eigen::Vector3d::Zero();
  auto add = [&](double x, double y, double l) {
    const Eigen::Vector3d r(1, x, y);
    AtA += r * r.transpose();
    Atb += l * r;
  };
  add(0, 0, lambda_[v]);
  for (int i = 0; i < d_; ++i) {
    const Vec3& u = star_->ring[i];
    add(u.x() / u.z(), u.y() / u.z(), lambda_[m_.tip(star_->out[i])]);
    halfExp_[i] = std::exp(lambda_[m_.tip(star_->out[i])] / 2);
  }
  fit_ = AtA.ldlt().solve(Atb);
  if (!fit_.allFinite()) fit_ = Eigen::Vector3d(lambda_[v], 0, 0);
}

double StarSmoother::measured(int i, double a, double b, double epv, double bgAngle) const {
  // Smallest angle of star triangle i with spokes a = |p u_i|, b = |p u_{i+1}|; bgAngle: the background's.
  if (!graded_) return bgAngle;
  const int j = (i + 1) % d_;
  const double o = tri_.length(HalfedgeMesh::next(star_->out[i])) * halfExp_[i] * halfExp_[j];
  return euclideanSmallestAngle(o, a * epv * halfExp_[i], b * epv * halfExp_[j]);
}

void StarSmoother::measureStar() {
  // The star's smallest angle and the sum of its triangles' smallest angles (their share of the mean smallest angle
  // of the mesh: moving v changes no other triangle).
  oldMin_ = INFINITY;
  oldSum_ = 0;
  for (int i = 0; i < d_; ++i) {
    const int h = star_->out[i];
    double t = std::min({fastCornerAngle(tri_, h), fastCornerAngle(tri_, HalfedgeMesh::next(h)),
                         fastCornerAngle(tri_, HalfedgeMesh::prev(h))});
    t = measured(i, tri_.length(h), tri_.length(star_->out[(i + 1) % d_]), std::exp(fit_[0] / 2), t);
    oldMin_ = std::min(oldMin_, t);
    oldSum_ += t;
  }
}

double StarSmoother::score(const Vec3& p) {
  // The sum of the per-triangle smallest angles of the moved star, or −∞ when the star folds, its smallest angle
  // decreases, or a triangle breaks a bound. The same validity test as isValidStarPosition (exact orientation,
  // triangle inequality), fused with the shape evaluation: this runs some tens of times per vertex.
  if (!p.allFinite() || (g_ == Background::Spherical && !(p.z() > 0))) return -INFINITY;
  dist_.resize(d_);
  for (int i = 0; i < d_; ++i) dist_[i] = model_.distance(p, star_->ring[i]);
  const double lambdaP = graded_ ? fit_[0] + fit_[1] * p.x() / p.z() + fit_[2] * p.y() / p.z() : 0.0;
  const double epv = std::exp(lambdaP / 2);
  double sum = 0;
  for (int i = 0; i < d_; ++i) {
    const int j = (i + 1) % d_, outerH = HalfedgeMesh::next(star_->out[i]);
    if (orientationSign(p, star_->ring[i], star_->ring[j]) <= 0) return -INFINITY;
    const double o = tri_.length(outerH), a = dist_[i], b = dist_[j];
    double tMin = 0, R = 0;
    if (!smallestAngleAndCircumradius(model_, p, star_->ring[i], star_->ring[j], o, a, b, !graded_, tMin, R))
      return -INFINITY;
    tMin = measured(i, a, b, epv, tMin);
    // The smallest angle of the star may not decrease (ties allowed).
    if (tMin < oldMin_) return -INFINITY;
    // Strict comparisons with the refinement's relative slack 1e-12 (processFace): a triangle at a bound is good.
    if (!(R <= options_.ratioBound * std::min({o, a, b}) * (1 + 1e-12))) return -INFINITY;
    if (std::isfinite(options_.epsilon)) {
      double lam = 0;
      if (graded_) lam = (lambdaP + lambda_[m_.tip(star_->out[i])] + lambda_[m_.tip(star_->out[j])]) / 3;
      if (!(R * std::exp(lam) <= options_.epsilon * (1 + 1e-12))) return -INFINITY;
    }
    // A boundary edge of the star stays unencroached: its apex angle (at p) at most 90° (Ruppert's test, with the
    // refinement's 1e-10 rad slack).
    if (m_.twin(outerH) == kInvalid && intrinsic::angleOpposite(g_, o, a, b) > M_PI / 2 + 1e-10) return -INFINITY;
    sum += tMin;
  }
  return sum;
}

bool StarSmoother::tryStartingPoints() {
  // The rule's target and the points halfway and a quarter of the way to it (the projective segment O → target is
  // the geodesic in every model). Returns whether any of them keeps the star valid.
  const Vec3 target = smoothingTarget(tri_, model_, *star_, options_.rule);
  best_ = oldSum_;
  bestP_ = BackgroundModel::origin();
  bool anyValid = false;
  for (int attempt = 0; attempt < 3; ++attempt) {
    const double t = std::ldexp(1.0, -attempt);
    const Vec3 p = attempt == 0 ? target : model_.normalize((1 - t) * BackgroundModel::origin() + t * target);
    if (isValidStarPosition(tri_, *star_, p)) anyValid = true;
    const double sc = score(p);
    if (sc > best_) best_ = sc, bestP_ = p;
  }
  return anyValid;
}

void StarSmoother::compassSearch() {
  // A compass search on the score around the best point so far: 8 directions; the step starts at 1/8 of the distance
  // to the nearest neighbour and is halved 3 times when no direction improves; at most 64 rounds. Steps are taken in
  // the straight-line chart (x/z, y/z) of the model, isometric to first order at the star's centre: the search needs
  // a pattern of nearby points, not exact distances, and the chart spares the exponential map.
  static const double kCos[8] = {1, M_SQRT1_2, 0, -M_SQRT1_2, -1, -M_SQRT1_2, 0, M_SQRT1_2};
  static const double kSin[8] = {0, M_SQRT1_2, 1, M_SQRT1_2, 0, -M_SQRT1_2, -1, -M_SQRT1_2};
  double nearest = INFINITY;
  for (int i = 0; i < d_; ++i) nearest = std::min(nearest, tri_.length(star_->out[i]));
  double step = 0.125 * nearest;
  for (int halvings = 0, iterations = 0; halvings < 3 && iterations < 64; ++iterations) {
    bool improved = false;
    for (int k = 0; k < 8; ++k) {
      const Vec3 q = model_.normalize(
          Vec3(bestP_.x() / bestP_.z() + step * kCos[k], bestP_.y() / bestP_.z() + step * kSin[k], 1.0));
      const double sc = score(q);
      if (sc > best_) best_ = sc, bestP_ = q, improved = true;
    }
    if (!improved) step /= 2, ++halvings;
  }
}

}  // namespace

std::string SmoothingOptions::validate() const {
  auto num = [](double x) {
    std::ostringstream s;
    s.precision(6);
    s << x;
    return s.str();
  };
  if (!(epsilon > 0)) return "smoothing: the size bound epsilon must be positive (+inf: none), got " + num(epsilon);
  if (!(ratioBound >= 1) || !std::isfinite(ratioBound))
    return "smoothing: the shape bound B must be at least 1 and finite, got " + num(ratioBound);
  return "";
}

SmoothingStatistics smoothFreeVertices(IntrinsicTriangulation& tri, Signposts& sp,
                                       std::vector<InputLocation>& locations, std::vector<double>& lambda,
                                       int inputVertices, const InputSurface& input,
                                       const std::vector<double>& inputLambda, const SmoothingOptions& options) {
  const std::string error = options.validate();
  if (!error.empty()) throw InputError(error);
  StarSmoother smoother(tri, sp, locations, lambda, input, inputLambda, options);
  SmoothingStatistics stats;
  for (int v = inputVertices; v < tri.mesh.nVertices(); ++v) smoother.smoothVertex(v, inputVertices, stats);
  return stats;
}

}  // namespace conformesh::refine
