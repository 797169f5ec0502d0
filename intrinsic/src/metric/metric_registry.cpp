// metric_registry.cpp — the table of built-in metric families with their parameters, and makeMetric, which builds one
// by name (see metric_registry.h).
#include "conformesh/intrinsic/metric/metric_registry.h"

#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/teapot_data.h"
#include "metric/family_checks.h"

namespace conformesh::intrinsic {

using metric_detail::fmt;
using metric_detail::require;

const std::vector<FamilyInfo>& metricFamilies() {
  static const std::vector<FamilyInfo> families = {
      {"sphere",
       "round sphere of radius R; chart u = longitude, v = colatitude (poles handled by an icosahedral base); "
       "K = 1/R^2, area 4 pi R^2, exact great-circle distances",
       {{"R", 1.0, "radius"}}},
      {"ellipsoid",
       "ellipsoid of revolution; chart u = longitude, v = conformal colatitude (the exact conformal map to the "
       "sphere); "
       "K = 1/(rho nu), distances by GeographicLib GeodesicExact",
       {{"a", 1.0, "equatorial radius"}, {"f", 0.3, "flattening (b = a(1-f); f < 0 prolate; -99 < f <= 0.99)"}}},
      {"torus",
       "torus of revolution (genus 1); chart u around the axis, v around the tube, both periodic; "
       "K = cos v / (r (R + r cos v)) of both signs, area 4 pi^2 R r",
       {{"R", 3.0, "radius of the centre circle (R > r)"}, {"r", 1.0, "tube radius"}}},
      {"kerr-newman",
       "Kerr-Newman black-hole horizon (Smarr 1973), sphere topology; u = phi, v = theta; area 4 pi (r+^2 + a^2); "
       "poles have K < 0 when a^2 > r+^2/3 (a/M > sqrt(3)/2 for Q = 0), where no embedding in R^3 exists",
       {{"M", 1.0, "mass"}, {"a", 0.5, "spin parameter J/M (a^2 + Q^2 <= M^2)"}, {"Q", 0.0, "charge"}}},
      {"flat-torus",
       "flat torus R^2 / (w1 Z + w2 Z), w1 = scale (1,0), w2 = scale tau; chart [0,1)^2 both periodic; K = 0",
       {{"tau_re", 0.0, "real part of the modulus tau"},
        {"tau_im", 1.0, "imaginary part of tau (> 0)"},
        {"scale", 1.0, "length of the first period w1"}}},
      {"spherical-cap",
       "geodesic disk of angular radius alpha on the sphere of radius R, geodesic polar chart; K = 1/R^2, "
       "area 2 pi R^2 (1 - cos alpha)",
       {{"R", 1.0, "sphere radius"}, {"alpha", 1.0, "angular radius in radians (0 < alpha < pi)"}}},
      {"hyperbolic-disk",
       "hyperbolic disk in the Poincare model, polar chart (u = angle, v = Euclidean radius); K = -1, "
       "area 4 pi sinh^2(radius/2), exact hyperbolic distances",
       {{"radius", 2.0, "geodesic (hyperbolic) radius"}}},
      {"gaussian-bump",
       "graph z = h exp(-(x^2+y^2)/(2 w^2)) over [-L,L]^2 (disk topology); K of both signs, total curvature "
       "-> 0 as L/w grows",
       {{"height", 1.0, "h"}, {"width", 0.5, "w"}, {"half_extent", 2.0, "L"}}},
      {"teapot-patch",
       "one bicubic Bezier patch of the Utah teapot (Newell's 32 patches; the paper's Fig. 8 experiment), chart "
       "[0,1]^2, pull-back metric of the patch, K from the second fundamental form",
       {{"patch", 4.0,
         "patch index 0..31 (0-3 rim, 4-11 body, 12-15 handle, 16-19 spout, 24-27 lid; 20-23 and "
         "28-31 are degenerate)"}}},
  };
  return families;
}

std::unique_ptr<SmoothMetric> makeMetric(const std::string& name, const std::map<std::string, double>& params) {
  const FamilyInfo* info = nullptr;
  for (const FamilyInfo& f : metricFamilies())
    if (f.name == name) info = &f;
  if (!info) {
    std::string known;
    for (const FamilyInfo& f : metricFamilies()) known += (known.empty() ? "" : ", ") + f.name;
    throw InputError("unknown metric family '" + name + "' (known: " + known + ")");
  }
  std::map<std::string, double> p;
  for (const FamilyParameter& fp : info->parameters) p[fp.name] = fp.defaultValue;
  for (const auto& [key, value] : params) {
    if (!p.count(key)) {
      std::string known;
      for (const FamilyParameter& fp : info->parameters) known += (known.empty() ? "" : ", ") + fp.name;
      throw InputError("metric family '" + name + "' has no parameter '" + key + "' (parameters: " + known + ")");
    }
    p[key] = value;
  }
  if (name == "sphere") return std::make_unique<RoundSphereMetric>(p["R"]);
  if (name == "ellipsoid") return std::make_unique<EllipsoidMetric>(p["a"], p["f"]);
  if (name == "torus") return std::make_unique<TorusMetric>(p["R"], p["r"]);
  if (name == "kerr-newman") return std::make_unique<KerrNewmanMetric>(p["M"], p["a"], p["Q"]);
  if (name == "flat-torus") return std::make_unique<FlatTorusMetric>(p["tau_re"], p["tau_im"], p["scale"]);
  if (name == "spherical-cap") return std::make_unique<SphericalCapMetric>(p["R"], p["alpha"]);
  if (name == "hyperbolic-disk") return std::make_unique<HyperbolicDiskMetric>(p["radius"]);
  if (name == "teapot-patch") {
    const double k = p["patch"];
    require(k == std::floor(k) && k >= 0 && k < kTeapotPatchCount, name,
            "patch must be an integer in 0..31, found " + fmt(k));
    return makeTeapotPatch(static_cast<int>(k));
  }
  // gaussian-bump
  const double h = p["height"], w = p["width"], L = p["half_extent"];
  require(std::isfinite(h) && std::isfinite(w) && w > 0 && std::isfinite(L) && L > 0, name,
          "height must be finite, width and half_extent finite and > 0");
  auto height = [h, w](double x, double y) -> HeightJet {
    const double e = h * std::exp(-(x * x + y * y) / (2 * w * w)), w2 = w * w;
    return {e, -x / w2 * e, -y / w2 * e, (x * x / w2 - 1) / w2 * e, x * y / (w2 * w2) * e, (y * y / w2 - 1) / w2 * e};
  };
  return makeFunctionGraph("gaussian-bump height=" + fmt(h) + " width=" + fmt(w) + " half_extent=" + fmt(L), -L, L, -L,
                           L, height);
}

}  // namespace conformesh::intrinsic
