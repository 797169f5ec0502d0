// horizon_surface.cpp — Strahlkörper shapes, their JSON form and fit, and the induced metric (horizon_surface.h;
// conventions and derivations in docs/horizons.md §2–§3).
#include "conformesh/intrinsic/metric/horizon_surface.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "metric/family_checks.h"

namespace conformesh::intrinsic {

namespace {

using metric_detail::fmt;

int ylmIndex(int l, int m) {
  return l * l + l + m;
}

// Fully normalized associated Legendre functions P̄_l^m(cos θ) = N_lm P_l^m(cos θ) (no Condon–Shortley phase) and
// their first two θ-derivatives, for 0 ≤ m ≤ l ≤ L, indexed l(l+1)/2 + m. The recursions (docs/horizons.md §2):
// P̄_00 = 1/√(4π); P̄_mm = √((2m+1)/(2m)) sin θ P̄_(m−1)(m−1); P̄_(m+1)m = √(2m+3) cos θ P̄_mm;
// P̄_lm = a_lm (cos θ P̄_(l−1)m − b_lm P̄_(l−2)m), a = √((4l²−1)/(l²−m²)), b = √(((l−1)²−m²)/(4(l−1)²−1));
// each differentiated in θ term by term (d cos θ = −sin θ, d sin θ = cos θ). Only orders m ≤ mMax are filled.
struct Legendre {
  std::vector<double> p, dp, ddp;
};
Legendre normalizedLegendre(int L, double theta, int mMax) {
  const double x = std::cos(theta), s = std::sin(theta);
  const int n = (L + 1) * (L + 2) / 2;
  Legendre P{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  auto at = [](int l, int m) { return l * (l + 1) / 2 + m; };
  P.p[0] = 1 / std::sqrt(4 * M_PI), P.dp[0] = 0, P.ddp[0] = 0;
  for (int m = 1; m <= mMax; ++m) {
    const int i = at(m, m), j = at(m - 1, m - 1);
    const double k = std::sqrt((2.0 * m + 1) / (2.0 * m));
    P.p[i] = k * s * P.p[j];
    P.dp[i] = k * (x * P.p[j] + s * P.dp[j]);
    P.ddp[i] = k * (-s * P.p[j] + 2 * x * P.dp[j] + s * P.ddp[j]);
  }
  for (int m = 0; m <= std::min(mMax, L - 1); ++m) {
    const int i = at(m + 1, m), j = at(m, m);
    const double k = std::sqrt(2.0 * m + 3);
    P.p[i] = k * x * P.p[j];
    P.dp[i] = k * (-s * P.p[j] + x * P.dp[j]);
    P.ddp[i] = k * (-x * P.p[j] - 2 * s * P.dp[j] + x * P.ddp[j]);
    for (int l = m + 2; l <= L; ++l) {
      const int c = at(l, m), p1 = at(l - 1, m), p2 = at(l - 2, m);
      const double a = std::sqrt((4.0 * l * l - 1) / (double(l) * l - double(m) * m));
      const double b = std::sqrt((double(l - 1) * (l - 1) - double(m) * m) / (4.0 * (l - 1) * (l - 1) - 1));
      P.p[c] = a * (x * P.p[p1] - b * P.p[p2]);
      P.dp[c] = a * (-s * P.p[p1] + x * P.dp[p1] - b * P.dp[p2]);
      P.ddp[c] = a * (-x * P.p[p1] - 2 * s * P.dp[p1] + x * P.ddp[p1] - b * P.ddp[p2]);
    }
  }
  return P;
}

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(describeAt(source, what));
}

}  // namespace

// The radius must be positive for the surface to be star-shaped (an immersion). Checked on a Gauss–Legendre ×
// uniform grid of (2 lMax + 8) × (4 lMax + 16) nodes: a sampling check, not a proof (docs/horizons.md §2).
void checkPositiveRadius(const Strahlkorper& s, const std::string& source) {
  const int nt = 2 * s.lMax() + 8, np = 4 * s.lMax() + 16;
  std::vector<double> x, w;
  gaussLegendre(nt, x, w);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) {
      const double theta = std::acos(x[i]), phi = 2 * M_PI * k / np;
      const double r = s.radius(theta, phi).r;
      if (!(r > 0))
        fail(source, "the Strahlkorper radius must be positive, found r=" + fmt(r) + " at theta=" + fmt(theta) +
                         " phi=" + fmt(phi));
    }
}

std::string toString(YlmConvention c) {
  switch (c) {
    case YlmConvention::Orthonormal: return "orthonormal";
    case YlmConvention::OrthonormalCondonShortley: return "orthonormal-condon-shortley";
    case YlmConvention::SpectreSpherepack: return "spectre-spherepack";
  }
  return "orthonormal";
}
YlmConvention parseYlmConvention(const std::string& name) {
  for (YlmConvention c :
       {YlmConvention::Orthonormal, YlmConvention::OrthonormalCondonShortley, YlmConvention::SpectreSpherepack})
    if (name == toString(c)) return c;
  throw InputError("unknown spherical-harmonic convention '" + name +
                   "': expected orthonormal, orthonormal-condon-shortley or spectre-spherepack");
}
double ylmConventionFactor(YlmConvention c, int m) {
  if (c == YlmConvention::OrthonormalCondonShortley) return std::abs(m) % 2 ? -1.0 : 1.0;
  if (c == YlmConvention::SpectreSpherepack) return m == 0 ? std::sqrt(M_PI / 2) : m > 0 ? std::sqrt(M_PI) : -std::sqrt(M_PI);
  return 1.0;
}

std::vector<YlmJet> realYlmJets(int lMax, double theta, double phi) {
  const Legendre P = normalizedLegendre(lMax, theta, lMax);
  std::vector<YlmJet> out((lMax + 1) * (lMax + 1));
  for (int l = 0; l <= lMax; ++l)
    for (int m = 0; m <= l; ++m) {
      const int i = l * (l + 1) / 2 + m;
      const double p = P.p[i], dp = P.dp[i], ddp = P.ddp[i];
      if (m == 0) {
        out[ylmIndex(l, 0)] = {p, dp, 0, ddp, 0, 0};
        continue;
      }
      const double c = M_SQRT2 * std::cos(m * phi), sn = M_SQRT2 * std::sin(m * phi), mm = m * m;
      out[ylmIndex(l, m)] = {p * c, dp * c, -m * p * sn, ddp * c, -m * dp * sn, -mm * p * c};
      out[ylmIndex(l, -m)] = {p * sn, dp * sn, m * p * c, ddp * sn, m * dp * c, -mm * p * sn};
    }
  return out;
}

// ---------------------------------------------------------------------------------------------------------------------
// Strahlkörper

Strahlkorper::Strahlkorper(const Eigen::Vector3d& center, const std::vector<Term>& terms) : c_(center) {
  if (!center.allFinite()) throw InputError("Strahlkorper: the center must be finite");
  for (const Term& t : terms) {
    if (t.l < 0 || std::abs(t.m) > t.l)
      throw InputError("Strahlkorper: coefficient (l=" + std::to_string(t.l) + ", m=" + std::to_string(t.m) +
                       ") needs l >= 0 and |m| <= l");
    lMax_ = std::max(lMax_, t.l);
    if (t.a != 0) mMax_ = std::max(mMax_, std::abs(t.m));
  }
  a_.assign((lMax_ + 1) * (lMax_ + 1), 0.0);
  std::vector<bool> seen(a_.size(), false);
  for (const Term& t : terms) {
    const std::string name = "(l=" + std::to_string(t.l) + ", m=" + std::to_string(t.m) + ")";
    if (!std::isfinite(t.a)) throw InputError("Strahlkorper: coefficient " + name + " is not finite");
    if (seen[ylmIndex(t.l, t.m)]) throw InputError("Strahlkorper: coefficient " + name + " is given twice");
    seen[ylmIndex(t.l, t.m)] = true;
    a_[ylmIndex(t.l, t.m)] = t.a;
  }
}
double Strahlkorper::coefficient(int l, int m) const {
  return l > lMax_ || std::abs(m) > l ? 0.0 : a_[ylmIndex(l, m)];
}
std::vector<Strahlkorper::Term> Strahlkorper::terms() const {
  std::vector<Term> out;
  for (int l = 0; l <= lMax_; ++l)
    for (int m = -l; m <= l; ++m)
      if (a_[ylmIndex(l, m)] != 0) out.push_back({l, m, a_[ylmIndex(l, m)]});
  return out;
}
RadiusJet Strahlkorper::radius(double theta, double phi) const {
  // Σ a_lm Y_lm with the Legendre table filled only up to the largest |m| present (axisymmetric shapes: O(l_max)).
  const Legendre P = normalizedLegendre(lMax_, theta, mMax_);
  RadiusJet r{0, 0, 0, 0, 0, 0};
  for (int m = 0; m <= mMax_; ++m) {
    const double c = m == 0 ? 1 : M_SQRT2 * std::cos(m * phi), sn = m == 0 ? 0 : M_SQRT2 * std::sin(m * phi);
    for (int l = m; l <= lMax_; ++l) {
      const int i = l * (l + 1) / 2 + m;
      // The cos(mφ) and sin(mφ) terms combined: A = a_lm c + a_l,−m s, and its φ-derivative m (a_l,−m c − a_lm s).
      const double ac = a_[ylmIndex(l, m)], as = m == 0 ? 0 : a_[ylmIndex(l, -m)];
      if (ac == 0 && as == 0) continue;
      const double A = ac * c + as * sn, Ap = m * (as * c - ac * sn), App = -double(m) * m * A;
      r.r += P.p[i] * A, r.rt += P.dp[i] * A, r.rtt += P.ddp[i] * A;
      r.rp += P.p[i] * Ap, r.rtp += P.dp[i] * Ap, r.rpp += P.p[i] * App;
    }
  }
  return r;
}
Eigen::Vector3d Strahlkorper::point(double theta, double phi) const {
  const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  return c_ + radius(theta, phi).r * n;
}

// ---------------------------------------------------------------------------------------------------------------------
// JSON

Strahlkorper parseStrahlkorperJson(const std::string& text, const std::string& source) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    fail(source, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) fail(source, "expected a JSON object with keys center and coefficients");
  if (!j.contains("center")) fail(source, "missing key 'center' (expected [x, y, z])");
  if (!j.contains("coefficients")) fail(source, "missing key 'coefficients' (expected a list of [l, m, a_lm])");
  const nlohmann::json& c = j["center"];
  if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number())
    fail(source, "'center': expected [x, y, z] (three numbers), found " + c.dump());
  YlmConvention convention = YlmConvention::Orthonormal;
  if (j.contains("convention")) {
    if (!j["convention"].is_string()) fail(source, "'convention': expected a string, found " + j["convention"].dump());
    try {
      convention = parseYlmConvention(j["convention"].get<std::string>());
    } catch (const InputError& e) {
      fail(source, e.what());
    }
  }
  const nlohmann::json& list = j["coefficients"];
  if (!list.is_array() || list.empty()) fail(source, "'coefficients': expected a non-empty list of [l, m, a_lm]");
  std::vector<Strahlkorper::Term> terms;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& t = list[i];
    if (!t.is_array() || t.size() != 3 || !t[0].is_number_integer() || !t[1].is_number_integer() || !t[2].is_number())
      fail(source, "coefficients[" + std::to_string(i) + "]: expected [l, m, a_lm] (two integers and a number), found " +
                       t.dump());
    const int l = t[0].get<int>(), m = t[1].get<int>();
    terms.push_back({l, m, ylmConventionFactor(convention, m) * t[2].get<double>()});
  }
  try {
    Strahlkorper s(Eigen::Vector3d(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()), terms);
    checkPositiveRadius(s, source);
    return s;
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind(source, 0) == 0) throw;
    fail(source, what);
  }
}

Strahlkorper readStrahlkorperJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the horizon shape file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parseStrahlkorperJson(ss.str(), path);
}

std::string strahlkorperToJson(const Strahlkorper& s) {
  nlohmann::json j;
  j["center"] = {s.center().x(), s.center().y(), s.center().z()};
  j["convention"] = "orthonormal";
  j["coefficients"] = nlohmann::json::array();
  for (const auto& t : s.terms()) j["coefficients"].push_back({t.l, t.m, t.a});
  return j.dump(1);
}

Strahlkorper fitStrahlkorper(const std::function<double(double, double)>& r, int lMax, const Eigen::Vector3d& center,
                             int oversample) {
  if (lMax < 0 || oversample < 1)
    throw InputError("fitStrahlkorper: need lMax >= 0 and oversample >= 1, found lMax=" + std::to_string(lMax) +
                     " oversample=" + std::to_string(oversample));
  const int nt = (lMax + 1) * oversample, np = (2 * lMax + 2) * oversample;
  std::vector<double> x, w;
  gaussLegendre(nt, x, w);
  std::vector<double> a((lMax + 1) * (lMax + 1), 0.0);
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) {
      const double theta = std::acos(x[i]), phi = 2 * M_PI * k / np, wk = w[i] * 2 * M_PI / np;
      const double ri = r(theta, phi);
      if (!std::isfinite(ri)) throw InputError("fitStrahlkorper: r is not finite at theta=" + fmt(theta) +
                                               " phi=" + fmt(phi));
      const std::vector<YlmJet> y = realYlmJets(lMax, theta, phi);
      for (std::size_t n = 0; n < a.size(); ++n) a[n] += wk * ri * y[n].y;
    }
  std::vector<Strahlkorper::Term> terms;
  for (int l = 0; l <= lMax; ++l)
    for (int m = -l; m <= l; ++m)
      if (l == 0 || std::abs(a[ylmIndex(l, m)]) > 1e-15 * std::abs(a[0])) terms.push_back({l, m, a[ylmIndex(l, m)]});
  return Strahlkorper(center, terms);
}

// ---------------------------------------------------------------------------------------------------------------------
// induced metric

HorizonSurfaceMetric::HorizonSurfaceMetric(Strahlkorper shape, std::shared_ptr<const SpatialMetric> gamma)
    : shape_(std::move(shape)), gamma_(std::move(gamma)) {
  if (!gamma_) throw InputError("horizon: no spatial metric given");
  checkPositiveRadius(shape_, "horizon");
  // γ must be evaluable and g positive definite on the sampling grid (a singular or indefinite γ is named here).
  const int nt = shape_.lMax() + 4, np = 2 * shape_.lMax() + 8;
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) {
      const double theta = M_PI * (i + 0.5) / nt, phi = 2 * M_PI * k / np;
      checkPositiveDefinite(g(phi, theta), "horizon " + description() + " at theta=" + fmt(theta) +
                                               " phi=" + fmt(phi));
    }
}
std::string HorizonSurfaceMetric::description() const {
  const Eigen::Vector3d& c = shape_.center();
  return "horizon l_max=" + std::to_string(shape_.lMax()) + " center=(" + fmt(c.x()) + "," + fmt(c.y()) + "," +
         fmt(c.z()) + ") in " + gamma_->description();
}
ChartDomain HorizonSurfaceMetric::domain() const {
  ChartDomain d;
  d.u0 = 0, d.u1 = 2 * M_PI, d.v0 = 0, d.v1 = M_PI;
  d.periodicU = true, d.poleAtV0 = true, d.poleAtV1 = true;
  return d;
}

HorizonSurfaceMetric::FirstJet HorizonSurfaceMetric::firstJet(double u, double v) const {
  const double phi = u, theta = v, st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  const RadiusJet r = shape_.radius(theta, phi);
  const Eigen::Vector3d n(st * cp, st * sp, ct), nt(ct * cp, ct * sp, -st), np(-st * sp, st * cp, 0);
  const Eigen::Vector3d ntp(-ct * sp, ct * cp, 0), npp(-st * cp, -st * sp, 0);
  // X = c + r n; index 0 = φ (u), 1 = θ (v). Xd[a] = ∂_a X, Xdd[a][b] = ∂_a ∂_b X.
  const Eigen::Vector3d Xp = r.rp * n + r.r * np, Xt = r.rt * n + r.r * nt;
  const Eigen::Vector3d Xpp = r.rpp * n + 2 * r.rp * np + r.r * npp;
  const Eigen::Vector3d Xtp = r.rtp * n + r.rt * np + r.rp * nt + r.r * ntp;
  const Eigen::Vector3d Xtt = r.rtt * n + 2 * r.rt * nt - r.r * n;
  const SpatialMetricJet G = gamma_->jet(shape_.center() + r.r * n);
  const Eigen::Vector3d X[2] = {Xp, Xt};
  const Eigen::Vector3d XX[2][2] = {{Xpp, Xtp}, {Xtp, Xtt}};
  FirstJet j;
  Eigen::Matrix2d* dg[2] = {&j.gu, &j.gv};
  for (int c = 0; c < 2; ++c) {
    const Eigen::Matrix3d dG = G.d[0] * X[c].x() + G.d[1] * X[c].y() + G.d[2] * X[c].z();  // ∂_c (γ ∘ X)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        j.g(a, b) = X[a].dot(G.g * X[b]);
        (*dg[c])(a, b) = XX[a][c].dot(G.g * X[b]) + X[a].dot(G.g * XX[b][c]) + X[a].dot(dG * X[b]);
      }
  }
  return j;
}

Eigen::Matrix2d HorizonSurfaceMetric::g(double u, double v) const {
  const double phi = u, theta = v, st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  const RadiusJet r = shape_.radius(theta, phi);
  const Eigen::Vector3d n(st * cp, st * sp, ct), nt(ct * cp, ct * sp, -st), np(-st * sp, st * cp, 0);
  const Eigen::Vector3d Xp = r.rp * n + r.r * np, Xt = r.rt * n + r.r * nt;
  const Eigen::Matrix3d G = gamma_->gamma(shape_.center() + r.r * n);
  Eigen::Matrix2d out;
  out(0, 0) = Xp.dot(G * Xp), out(1, 1) = Xt.dot(G * Xt), out(0, 1) = out(1, 0) = Xp.dot(G * Xt);
  return out;
}

MetricJet HorizonSurfaceMetric::jet(double u, double v) const {
  // Second derivatives: fourth-order central differences of the analytic first derivatives, step h = 2e-3
  // (truncation ~ h⁴/30·|g⁽⁵⁾| ≈ 5e-13 for g varying on scale 1; round-off ~ ε/h ≈ 1e-13).
  const double h = 2e-3;
  auto diff = [&](auto&& f) -> Eigen::Matrix2d {
    return (8 * (f(h) - f(-h)) - (f(2 * h) - f(-2 * h))) / (12 * h);
  };
  const FirstJet c = firstJet(u, v);
  MetricJet j;
  j.g = c.g, j.gu = c.gu, j.gv = c.gv;
  j.guu = diff([&](double t) -> Eigen::Matrix2d { return firstJet(u + t, v).gu; });
  j.guv = diff([&](double t) -> Eigen::Matrix2d { return firstJet(u, v + t).gu; });
  j.gvv = diff([&](double t) -> Eigen::Matrix2d { return firstJet(u, v + t).gv; });
  return j;
}

// makeHorizonMetric, readHorizonMetadata and makeHorizonMetricFromFile read every shape form: strahlkorper_io.cpp.

}  // namespace conformesh::intrinsic
