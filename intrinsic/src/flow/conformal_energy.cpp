// conformal_energy.cpp — Milnor's Lobachevsky function and the Euclidean vertex-scaling energy (conformal_energy.h).
#include "conformesh/intrinsic/flow/conformal_energy.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "flow/face_angles.h"

namespace conformesh::intrinsic {

namespace {

constexpr int kClausenTerms = 30;  // term n ≤ θ (1/2)^{2n}/n² on |θ| ≤ π: below 2⁻⁶⁰ relative from n = 30

// ζ(2n), n = 1..kClausenTerms: Σ_{k<K} k^{−s} and the Euler–Maclaurin tail K^{1−s}/(s−1) + K^{−s}/2 + s K^{−s−1}/12
// − s(s+1)(s+2) K^{−s−3}/720 (K = 30: the next term is below 10⁻¹⁵ of ζ(4)'s contribution).
std::array<double, kClausenTerms + 1> zetaEven() {
  std::array<double, kClausenTerms + 1> z{};
  const double K = 30;
  for (int n = 1; n <= kClausenTerms; ++n) {
    const double s = 2 * n;
    double sum = 0;
    for (int k = 29; k >= 1; --k) sum += std::pow(double(k), -s);
    sum += std::pow(K, 1 - s) / (s - 1) + 0.5 * std::pow(K, -s) + s * std::pow(K, -s - 1) / 12 -
           s * (s + 1) * (s + 2) * std::pow(K, -s - 3) / 720;
    z[n] = sum;
  }
  z[1] = M_PI * M_PI / 6;
  return z;
}

// Cl₂(θ) for |θ| ≤ π: θ − θ log|θ| + Σ_{n≥1} ζ(2n)/(n(2n+1)) θ (θ/2π)^{2n} (the Bernoulli series, |B_2n| =
// 2 (2n)! ζ(2n)/(2π)^{2n}).
double clausenReduced(double theta) {
  static const std::array<double, kClausenTerms + 1> zeta = zetaEven();
  if (theta == 0) return 0;
  const double q = (theta / (2 * M_PI)) * (theta / (2 * M_PI));
  double sum = 0, power = 1;
  for (int n = 1; n <= kClausenTerms; ++n) {
    power *= q;
    sum += zeta[n] / (n * (2.0 * n + 1)) * power;
  }
  return theta - theta * std::log(std::abs(theta)) + theta * sum;
}

}  // namespace

double lobachevsky(double x) {
  // Л is π-periodic: reduce 2x to [−π, π].
  double t = std::remainder(2 * x, 2 * M_PI);
  return 0.5 * clausenReduced(t);
}

namespace detail {

// The face sum of conformalEnergy from faces evaluated at the current u (evaluateFaces).
double faceEnergy(const DiscreteConformalMetric& metric, const std::vector<FaceGeometry>& faces, double& magnitude) {
  double energy = 0;
  for (int f = 0; f < metric.mesh().nFaces(); ++f) {
    if (metric.isFrozen(f)) continue;
    const FaceGeometry& g = faces[f];
    for (int k = 0; k < 3; ++k) {
      const double lambda = 2 * std::log(g.L[k]);
      const double term = (g.theta[k] - 0.5 * M_PI) * lambda + 2 * lobachevsky(g.theta[k]);
      energy += term;
      magnitude += std::abs(term) + std::abs(lambda);
    }
  }
  return energy;
}

}  // namespace detail

double conformalEnergy(const DiscreteConformalMetric& metric, const std::vector<double>& targetAngleSum,
                       double* magnitude) {
  if (metric.geometry() != Background::Euclidean)
    throw InputError("conformalEnergy: implemented for the Euclidean background only");
  if (static_cast<int>(targetAngleSum.size()) != metric.nVertices())
    throw InputError("conformalEnergy: expected " + std::to_string(metric.nVertices()) + " target angle sums, found " +
                     std::to_string(targetAngleSum.size()));
  std::vector<double> length, sums;
  std::vector<detail::FaceGeometry> faces;
  detail::evaluateFaces(metric, length, sums, faces);
  double scale = 0;
  double energy = detail::faceEnergy(metric, faces, scale);
  for (int v = 0; v < metric.nVertices(); ++v)
    if (std::isfinite(targetAngleSum[v])) {
      energy += targetAngleSum[v] * metric.u()[v];
      scale += std::abs(targetAngleSum[v] * metric.u()[v]);
    }
  if (magnitude) *magnitude = scale;
  return energy;
}

}  // namespace conformesh::intrinsic
