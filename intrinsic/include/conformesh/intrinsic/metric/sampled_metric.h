// sampled_metric.h — a sampled metric field (sampled_field.h) as a SmoothMetric: tensor-product cubic B-splines of
// g_uu, g_uv, g_vv (C², fourth-order accurate in g, second-order in its second derivatives and hence in K).
// Pole-to-pole fields are interpolated in their regular form (g_uu/sin²v, g_uv/sin v, g_vv) on the doubled great
// circle and g is rebuilt with the exact sin v factors, so g is smooth through the pole and exactly degenerate at it
// (docs/metrics.md, "Sampled fields", derives this). Depends on sampled_field.h only; no file reading.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "conformesh/intrinsic/metric/sampled_field.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

class SampledMetric : public SmoothMetric {
 public:
  // Validates the field (shape, finiteness, positive-definiteness of every sample, naming the line or grid node) and
  // builds the splines.
  explicit SampledMetric(const SampledField& field);
  std::string family() const override { return "field"; }
  std::string description() const override;
  ChartDomain domain() const override { return field_.domain; }
  Eigen::Matrix2d g(double u, double v) const override;
  MetricJet jet(double u, double v) const override;  // analytic derivatives of the spline interpolant

 private:
  struct Spline2D {
    std::vector<double> c;  // coefficients, (nCu × nCv), u fastest
  };
  struct Axis {
    double x0 = 0, h = 1;  // node x_i = x0 + i h
    int n = 0, nc = 0;     // nodes, coefficients
    bool periodic = false;
  };
  // Value and first/second derivatives of one spline at (u, v): {f, fu, fv, fuu, fuv, fvv}.
  std::array<double, 6> evaluate(const Spline2D& s, double u, double v) const;

  SampledField field_;
  bool poles_ = false;
  Axis au_, av_;
  Spline2D suu_, suv_, svv_;
};

}  // namespace conformesh::intrinsic
