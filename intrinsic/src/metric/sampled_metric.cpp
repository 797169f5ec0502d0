// sampled_metric.cpp — spline interpolation of a sampled metric field (see sampled_metric.h): validation of the
// samples, the tensor-product cubic B-spline coefficients, and evaluation of g and its derivatives.
#include "conformesh/intrinsic/metric/sampled_metric.h"

#include <cmath>
#include <sstream>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/sampled_field_checks.h"

namespace conformesh::intrinsic {

// =====================================================================================================================
// spline interpolation

namespace {

std::string sourceLine(const std::string& source, int line) {
  return source + ":" + std::to_string(line);
}

// Coefficients of the 1-D cubic B-spline interpolant of each column of `data` (n rows): periodic (circulant
// (1, 4, 1)/6) or not-a-knot (third derivative continuous at the second and second-to-last node; n + 2 coefficients).
Eigen::MatrixXd splineCoefficients(const Eigen::MatrixXd& data, bool periodic) {
  const int n = static_cast<int>(data.rows()), nc = periodic ? n : n + 2;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    for (int m = -1; m <= 1; ++m) {
      const int col = periodic ? (i + m + n) % n : i + m + 1;
      t.emplace_back(i, col, m == 0 ? 4.0 / 6 : 1.0 / 6);
    }
  if (!periodic) {
    const double nak[5] = {1, -4, 6, -4, 1};
    for (int k = 0; k < 5; ++k) t.emplace_back(n, k, nak[k]), t.emplace_back(n + 1, n - 3 + k, nak[k]);
  }
  Eigen::SparseMatrix<double> A(nc, nc);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success) throw InputError("sampled metric: spline system is singular (grid too small?)");
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nc, data.cols());
  rhs.topRows(n) = data;
  return lu.solve(rhs);
}

// Uniform cubic B-spline basis on a cell, t ∈ [0,1], with first and second t-derivatives.
void basis(double t, double b[4], double db[4], double ddb[4]) {
  const double s = 1 - t;
  b[0] = s * s * s / 6, b[1] = (3 * t * t * t - 6 * t * t + 4) / 6, b[2] = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
  b[3] = t * t * t / 6;
  db[0] = -s * s / 2, db[1] = (3 * t * t - 4 * t) / 2, db[2] = (-3 * t * t + 2 * t + 1) / 2, db[3] = t * t / 2;
  ddb[0] = s, ddb[1] = 3 * t - 2, ddb[2] = 1 - 3 * t, ddb[3] = t;
}

}  // namespace

SampledMetric::SampledMetric(const SampledField& field) : field_(field) {
  const SampledField& f = field_;
  const std::string& src = f.source;
  poles_ = f.domain.poleAtV0 && f.domain.poleAtV1;
  const int minU = f.domain.periodicU ? 3 : 4, minV = (f.domain.periodicV || poles_) ? 2 : 4;
  if (f.nu < minU || f.nv < minV)
    throw InputError(src + ": wrong grid shape: need at least " + std::to_string(minU) + " x " + std::to_string(minV) +
                     " nodes for a cubic spline on this chart, found " + std::to_string(f.nu) + " x " +
                     std::to_string(f.nv));
  if (static_cast<int>(f.guu.size()) != f.nu * f.nv || f.guv.size() != f.guu.size() || f.gvv.size() != f.guu.size())
    throw InputError(src + ": wrong grid shape: " + std::to_string(f.nu) + " x " + std::to_string(f.nv) + " needs " +
                     std::to_string(f.nu * f.nv) + " samples of each field, found " + std::to_string(f.guu.size()) +
                     ", " + std::to_string(f.guv.size()) + ", " + std::to_string(f.gvv.size()));
  if (poles_ && f.nu % 2 != 0)
    throw InputError(src + ": a pole-to-pole field needs an even NU (the sample across the pole is at u + pi), found " +
                     std::to_string(f.nu));
  // The mistakes of handing a field over, named before the per-sample checks (a sphere's g_uu = 0 end row would
  // otherwise be reported as a sample that is not positive definite).
  checkFieldGridOrder(f);
  checkFieldPoles(f);
  for (int j = 0; j < f.nv; ++j)
    for (int i = 0; i < f.nu; ++i) {
      const int k = j * f.nu + i;
      Eigen::Matrix2d g;
      g << f.guu[k], f.guv[k], f.guv[k], f.gvv[k];
      const std::string where =
          f.lines.empty() ? src + ": grid node (" + std::to_string(i) + ", " + std::to_string(j) + ")"
                          : sourceLine(src, f.lines[k]) + " (grid node " + std::to_string(i) + ", " + std::to_string(j) + ")";
      checkPositiveDefinite(g, where);
    }

  au_.periodic = f.domain.periodicU, au_.n = f.nu, au_.x0 = f.domain.u0;
  au_.h = (f.domain.u1 - f.domain.u0) / (au_.periodic ? f.nu : f.nu - 1);
  au_.nc = au_.periodic ? f.nu : f.nu + 2;
  // v: the doubled great circle for pole-to-pole fields, else as in the file.
  const int rows = poles_ ? 2 * f.nv : f.nv;
  av_.periodic = poles_ || f.domain.periodicV, av_.n = rows;
  av_.h = poles_ ? M_PI / f.nv : (f.domain.v1 - f.domain.v0) / (f.domain.periodicV ? f.nv : f.nv - 1);
  av_.x0 = poles_ ? 0.5 * av_.h : f.domain.v0;
  av_.nc = av_.periodic ? rows : rows + 2;

  // Regular forms on the (possibly doubled) grid, rows = v, columns = u.
  Eigen::MatrixXd A(rows, f.nu), B(rows, f.nu), E(rows, f.nu);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < f.nu; ++i) {
      int jj = j, ii = i;
      if (poles_ && j >= f.nv) jj = 2 * f.nv - 1 - j, ii = (i + f.nu / 2) % f.nu;
      const int k = jj * f.nu + ii;
      if (poles_) {
        const double s = std::sin(f.nodeV(jj));  // the regular forms are even across the pole (sampled_metric.h)
        A(j, i) = f.guu[k] / (s * s), B(j, i) = f.guv[k] / s, E(j, i) = f.gvv[k];
      } else {
        A(j, i) = f.guu[k], B(j, i) = f.guv[k], E(j, i) = f.gvv[k];
      }
    }
  // Tensor product: splines along u for every row, then along v for every u-coefficient column.
  auto build = [&](const Eigen::MatrixXd& data, Spline2D& s) {
    const Eigen::MatrixXd cu = splineCoefficients(data.transpose(), au_.periodic);  // nCu × rows
    const Eigen::MatrixXd cuv = splineCoefficients(cu.transpose(), av_.periodic);   // nCv × nCu
    s.c.resize(static_cast<size_t>(av_.nc) * au_.nc);
    for (int b = 0; b < av_.nc; ++b)
      for (int a = 0; a < au_.nc; ++a) s.c[static_cast<size_t>(b) * au_.nc + a] = cuv(b, a);
  };
  build(A, suu_);
  build(B, suv_);
  build(E, svv_);
}

std::string SampledMetric::description() const {
  return "field " + field_.source + " (" + std::to_string(field_.nu) + " x " + std::to_string(field_.nv) + " " +
         toString(field_.domain.shape()) + " grid)";
}

std::array<double, 6> SampledMetric::evaluate(const Spline2D& s, double u, double v) const {
  auto locate = [](const Axis& ax, double x, int idx[4], double& t) {
    const double q = (x - ax.x0) / ax.h;
    int k = static_cast<int>(std::floor(q));
    if (!ax.periodic) k = std::min(std::max(k, 0), ax.n - 2);  // beyond the ends: the end cubic's extension
    t = q - k;
    for (int m = 0; m < 4; ++m) {
      const int c = k + m - 1;
      idx[m] = ax.periodic ? ((c % ax.nc) + ax.nc) % ax.nc : c + 1;
    }
  };
  int iu[4], iv[4];
  double tu, tv, bu[4], dbu[4], ddbu[4], bv[4], dbv[4], ddbv[4];
  locate(au_, u, iu, tu);
  locate(av_, v, iv, tv);
  basis(tu, bu, dbu, ddbu);
  basis(tv, bv, dbv, ddbv);
  std::array<double, 6> r{};
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const double c = s.c[static_cast<size_t>(iv[b]) * au_.nc + iu[a]];
      r[0] += c * bu[a] * bv[b];
      r[1] += c * dbu[a] * bv[b];
      r[2] += c * bu[a] * dbv[b];
      r[3] += c * ddbu[a] * bv[b];
      r[4] += c * dbu[a] * dbv[b];
      r[5] += c * bu[a] * ddbv[b];
    }
  const double hu = au_.h, hv = av_.h;
  r[1] /= hu, r[2] /= hv, r[3] /= hu * hu, r[4] /= hu * hv, r[5] /= hv * hv;
  return r;
}

Eigen::Matrix2d SampledMetric::g(double u, double v) const {
  const double A = evaluate(suu_, u, v)[0], B = evaluate(suv_, u, v)[0], E = evaluate(svv_, u, v)[0];
  const double s = poles_ ? std::sin(v) : 1.0;
  Eigen::Matrix2d m;
  m << A * s * s, B * s, B * s, E;
  return m;
}

MetricJet SampledMetric::jet(double u, double v) const {
  const auto A = evaluate(suu_, u, v), B = evaluate(suv_, u, v), E = evaluate(svv_, u, v);
  // Multiply the regular forms back by sin²v and sin v (product rule); without poles the factors are 1.
  const double s = poles_ ? std::sin(v) : 1.0, c = poles_ ? std::cos(v) : 0.0;
  const double s2 = s * s, s2v = 2 * s * c, s2vv = poles_ ? 2 * (c * c - s * s) : 0.0;
  const double s1v = c, s1vv = poles_ ? -s : 0.0;
  MetricJet j;
  auto set = [](Eigen::Matrix2d& m, double guu, double guv, double gvv) { m << guu, guv, guv, gvv; };
  set(j.g, A[0] * s2, B[0] * s, E[0]);
  set(j.gu, A[1] * s2, B[1] * s, E[1]);
  set(j.gv, A[2] * s2 + A[0] * s2v, B[2] * s + B[0] * s1v, E[2]);
  set(j.guu, A[3] * s2, B[3] * s, E[3]);
  set(j.guv, A[4] * s2 + A[1] * s2v, B[4] * s + B[1] * s1v, E[4]);
  set(j.gvv, A[5] * s2 + 2 * A[2] * s2v + A[0] * s2vv, B[5] * s + 2 * B[2] * s1v + B[0] * s1vv, E[5]);
  return j;
}

}  // namespace conformesh::intrinsic
