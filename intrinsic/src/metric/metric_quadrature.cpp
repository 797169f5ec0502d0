// metric_quadrature.cpp — adaptive tensor Gauss–Legendre quadrature on chart rectangles and triangles (see
// metric_quadrature.h).
#include "conformesh/intrinsic/metric/metric_quadrature.h"

#include <cmath>
#include <queue>
#include <sstream>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  if (n < 1 || n > 64)
    throw InputError("Gauss-Legendre rule: node count must lie in 1..64, found " + std::to_string(n));
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1;
    // Newton on P_n; 100 iterations is far beyond the ~5 that quadratic convergence from these guesses needs.
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pm = n == 1 ? 1 : p0;
      dp = n * (x * pn - pm) / (x * x - 1);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2 / ((1 - x * x) * dp * dp);
  }
}

const GaussLegendreRule& gaussLegendreRule(int n) {
  if (n < 1 || n > 64)
    throw InputError("Gauss-Legendre rule: node count must lie in 1..64, found " + std::to_string(n));
  // All 64 rules at once on first use (a few 10⁵ flops); a function-local static is initialized exactly once even
  // under OpenMP threads (C++11 [stmt.dcl]/4).
  static const std::vector<GaussLegendreRule> rules = [] {
    std::vector<GaussLegendreRule> r(65);
    for (int k = 1; k <= 64; ++k) {
      GaussLegendreRule& g = r[k];
      gaussLegendre(k, g.nodes, g.weights);
      for (double x : g.nodes) g.unitNodes.push_back(0.5 * (x + 1));
      for (double w : g.weights) g.unitWeights.push_back(w * 0.5);
    }
    return r;
  }();
  return rules[n];
}

const double GaussKronrod15::nodes[kNodes] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                              0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
const double GaussKronrod15::kronrodWeights[kNodes] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
    0.140653259715525918745189590510238, 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
const double GaussKronrod15::gaussWeights[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780, 0.381830050505118944950369775488975,
    0.417959183673469387755102040816327};

namespace {

// A cell is a rectangle or a triangle in the chart; both are images of the unit square.
struct Cell {
  bool triangle = false;
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero(), c = Eigen::Vector2d::Zero();
  // rectangle: a = (u0,v0), b = (u1,v1) (c unused); triangle: corners
};

double applyRule(const ChartFunction& f, const Cell& cell, const GaussLegendreRule& r, long& evals) {
  double sum = 0;
  const int n = static_cast<int>(r.unitNodes.size());
  if (!cell.triangle) {
    const Eigen::Vector2d d = cell.b - cell.a;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        sum += r.unitWeights[i] * r.unitWeights[j] *
               f(cell.a.x() + r.unitNodes[i] * d.x(), cell.a.y() + r.unitNodes[j] * d.y());
    evals += n * n;
    return sum * d.x() * d.y();
  }
  // Collapsed (Duffy) map p = a + s((1 − t)(b − a) + t(c − a)), Jacobian s·|det(b − a, c − a)|.
  const Eigen::Vector2d e1 = cell.b - cell.a, e2 = cell.c - cell.a;
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double s = r.unitNodes[i], t = r.unitNodes[j];
      const Eigen::Vector2d p = cell.a + s * ((1 - t) * e1 + t * e2);
      sum += r.unitWeights[i] * r.unitWeights[j] * s * f(p.x(), p.y());
    }
  evals += n * n;
  return sum * det;  // signed: callers that want a measure take the orientation into account
}

// The four midpoint children of a triangle cell (rectangles are halved in makeNodeByRule instead).
std::array<Cell, 4> triangleChildren(const Cell& c) {
  std::array<Cell, 4> k;
  const Eigen::Vector2d ab = 0.5 * (c.a + c.b), bc = 0.5 * (c.b + c.c), ca = 0.5 * (c.c + c.a);
  // Midpoint subdivision; all four children keep the parent's orientation (the middle one as (bc, ca, ab)).
  k[0] = {true, c.a, ab, ca};
  k[1] = {true, ab, c.b, bc};
  k[2] = {true, ca, bc, c.c};
  k[3] = {true, bc, ca, ab};
  return k;
}

// A cell with its own rule value q and its children's values; it contributes Σ children to the integral and
// |q − Σ children| to the error estimate. Rectangles are halved along one direction: both halvings are tried and the
// one that changes the value more (the direction in which the integrand is under-resolved) is kept, so a feature
// that varies in one direction only (a ridge of curvature along a parallel) costs a 1-D, not a 2-D, refinement.
// Triangles are split into four by their edge midpoints.
struct Node {
  Cell cell;
  std::array<Cell, 4> kids;
  std::array<double, 4> qk{};
  int nk = 0;
  double sum = 0, err = 0;
  int depth = 0;
  bool operator<(const Node& o) const { return err < o.err; }
};

Node makeNodeByRule(const ChartFunction& f, const Cell& cell, double q, int depth, const GaussLegendreRule& r,
                    long& evals) {
  Node n;
  n.cell = cell;
  n.depth = depth;
  if (cell.triangle) {
    n.kids = triangleChildren(cell);
    n.nk = 4;
    for (int i = 0; i < 4; ++i) n.sum += n.qk[i] = applyRule(f, n.kids[i], r, evals);
    n.err = std::abs(n.sum - q);
    return n;
  }
  const Eigen::Vector2d m = 0.5 * (cell.a + cell.b);
  Cell u1 = cell, u2 = cell, v1 = cell, v2 = cell;
  u1.b.x() = m.x(), u2.a.x() = m.x();
  v1.b.y() = m.y(), v2.a.y() = m.y();
  const double qu1 = applyRule(f, u1, r, evals), qu2 = applyRule(f, u2, r, evals);
  const double qv1 = applyRule(f, v1, r, evals), qv2 = applyRule(f, v2, r, evals);
  const double eu = std::abs(qu1 + qu2 - q), ev = std::abs(qv1 + qv2 - q);
  n.nk = 2;
  // Ties (within a factor 2, e.g. both at round-off, or an indicator jump no node sees) halve the longer side, so
  // cells never degenerate into slivers that keep straddling a region boundary.
  const Eigen::Vector2d d = cell.b - cell.a;
  const bool splitU = (eu > 2 * ev) || (ev <= 2 * eu && d.x() >= d.y());
  if (splitU) {
    n.kids[0] = u1, n.kids[1] = u2, n.qk[0] = qu1, n.qk[1] = qu2;
  } else {
    n.kids[0] = v1, n.kids[1] = v2, n.qk[0] = qv1, n.qk[1] = qv2;
  }
  n.sum = n.qk[0] + n.qk[1];
  n.err = std::max(eu, ev);
  return n;
}

// Optional lower bound on a cell's error that the rule cannot see (a region boundary crossing the cell).
using ErrorFloor = std::function<double(const Cell&)>;

Node makeNode(const ChartFunction& f, const Cell& cell, double q, int depth, const GaussLegendreRule& r, long& evals,
              const ErrorFloor& floor) {
  Node n = makeNodeByRule(f, cell, q, depth, r, evals);
  if (floor) {
    double fl = 0;
    for (int i = 0; i < n.nk; ++i) fl += floor(n.kids[i]);
    n.err = std::max(n.err, fl);
  }
  return n;
}

// Globally adaptive (as QUADPACK's qag): always split the cell with the largest error estimate, until the summed
// estimate meets the tolerance, the depth limit leaves nothing to split, or the evaluation budget is spent.
QuadratureResult integrateCells(const ChartFunction& f, const std::vector<Cell>& cells, const QuadratureOptions& o,
                                const std::string& what, const ErrorFloor& floor = {}) {
  const GaussLegendreRule& r = gaussLegendreRule(o.gaussPoints);
  long evals = 0;
  std::priority_queue<Node> open;
  std::vector<Node> done;  // at the depth limit
  double value = 0, error = 0;
  for (const Cell& c : cells) {
    Node n = makeNode(f, c, applyRule(f, c, r, evals), 0, r, evals, floor);
    value += n.sum, error += n.err;
    open.push(std::move(n));
  }
  auto target = [&] { return std::max(o.absoluteTolerance, o.relativeTolerance * std::abs(value)); };
  // Two levels are always taken so that a coincidental agreement of a coarse rule cannot end the refinement.
  while (!open.empty() && (error > target() || open.top().depth < 2) && evals < o.maxEvaluations) {
    Node n = open.top();
    open.pop();
    if (n.depth >= o.maxDepth) {
      done.push_back(std::move(n));
      continue;
    }
    value -= n.sum, error -= n.err;
    for (int i = 0; i < n.nk; ++i) {
      Node k = makeNode(f, n.kids[i], n.qk[i], n.depth + 1, r, evals, floor);
      value += k.sum, error += k.err;
      open.push(std::move(k));
    }
  }
  // Re-add from scratch: the running sums above accumulate cancellation error over many updates.
  value = 0, error = 0;
  for (const Node& n : done) value += n.sum, error += n.err;
  while (!open.empty()) value += open.top().sum, error += open.top().err, open.pop();
  if (!std::isfinite(value)) throw InputError(what + ": the integrand is not finite somewhere in the region");
  if (error > target() && o.throwOnFailure) {
    std::ostringstream s;
    s << what << ": adaptive quadrature stopped (depth limit " << o.maxDepth << ", " << evals << " of at most "
      << o.maxEvaluations << " evaluations) with estimated error " << error << " above the tolerance " << target()
      << " (value " << value << ")";
    throw ConvergenceError(s.str());
  }
  return {value, error, evals};
}

}  // namespace

QuadratureResult integrateOverRectangle(const ChartFunction& f, double u0, double u1, double v0, double v1,
                                        const QuadratureOptions& options) {
  Cell c;
  c.a = {u0, v0}, c.b = {u1, v1};
  QuadratureResult r = integrateCells(f, {c}, options, "rectangle quadrature");
  return r;
}

QuadratureResult integrateOverTriangle(const ChartFunction& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       const Eigen::Vector2d& c, const QuadratureOptions& options) {
  QuadratureResult r = integrateOverTriangles(f, {{a, b, c}}, options);
  return r;
}

QuadratureResult integrateOverTriangles(const ChartFunction& f, const std::vector<std::array<Eigen::Vector2d, 3>>& tris,
                                        const QuadratureOptions& options) {
  std::vector<Cell> cells;
  for (const auto& t : tris) {
    Cell c{true, t[0], t[1], t[2]};
    const Eigen::Vector2d e1 = t[1] - t[0], e2 = t[2] - t[0];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(c.b, c.c);  // positive orientation: a measure
    cells.push_back(c);
  }
  return integrateCells(f, cells, options, "triangle quadrature");
}

QuadratureResult integrateOverPolygon(const ChartFunction& f, const std::vector<Eigen::Vector2d>& polygon,
                                      const QuadratureOptions& options) {
  if (polygon.size() < 3)
    throw InputError("polygon quadrature: a polygon needs at least 3 vertices, found " +
                     std::to_string(polygon.size()));
  // Signed fan from vertex 0: ∫_P f = Σ sign(T_i) ∫_{T_i} f for any simple polygon. The triangles keep their
  // orientation, so the rule values carry the sign; a negatively oriented polygon is flipped at the end.
  std::vector<Cell> cells;
  double signedArea = 0;
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    Cell c{true, polygon[0], polygon[i], polygon[i + 1]};
    const Eigen::Vector2d e1 = c.b - c.a, e2 = c.c - c.a;
    signedArea += e1.x() * e2.y() - e1.y() * e2.x();
    cells.push_back(c);
  }
  QuadratureResult r = integrateCells(f, cells, options, "polygon quadrature");
  if (signedArea < 0) r.value = -r.value;
  return r;
}

QuadratureResult integrateOverRegion(const ChartFunction& f, double u0, double u1, double v0, double v1,
                                     const std::function<bool(double, double)>& inside,
                                     const QuadratureOptions& options) {
  auto g = [&](double u, double v) { return inside(u, v) ? f(u, v) : 0.0; };
  // A rule cannot see where an indicator jumps, so a cell whose 3×3 sample points (corners, edge midpoints, centre)
  // disagree about membership gets the error floor |cell| · max |f| there: refinement then follows the boundary and the
  // estimate stays honest (boundary features smaller than a cell between sample points can still be missed).
  auto floor = [&](const Cell& cell) {
    int in = 0;
    double fmax = 0;
    const Eigen::Vector2d d = cell.b - cell.a;
    for (int i = 0; i <= 2; ++i)
      for (int j = 0; j <= 2; ++j) {
        const double u = cell.a.x() + 0.5 * i * d.x(), v = cell.a.y() + 0.5 * j * d.y();
        if (inside(u, v)) ++in, fmax = std::max(fmax, std::abs(f(u, v)));
      }
    return (in == 0 || in == 9) ? 0.0 : fmax * d.x() * d.y();
  };
  Cell c;
  c.a = {u0, v0}, c.b = {u1, v1};
  return integrateCells(g, {c}, options, "region quadrature", floor);
}

ChartFunction areaDensity(const SmoothMetric& m) {
  return [&m](double u, double v) { return m.areaElement(u, v); };
}
ChartFunction curvatureDensity(const SmoothMetric& m) {
  return [&m](double u, double v) { return m.gaussianCurvature(u, v) * m.areaElement(u, v); };
}

QuadratureResult metricArea(const SmoothMetric& m, const QuadratureOptions& options) {
  const ChartDomain d = m.domain();
  return integrateOverRectangle(areaDensity(m), d.u0, d.u1, d.v0, d.v1, options);
}
QuadratureResult metricTotalCurvature(const SmoothMetric& m, const QuadratureOptions& options) {
  const ChartDomain d = m.domain();
  return integrateOverRectangle(curvatureDensity(m), d.u0, d.u1, d.v0, d.v1, options);
}

}  // namespace conformesh::intrinsic
