// sampled_field_checks.cpp — the structural checks of a sampled field (see sampled_field_checks.h).
#include "conformesh/intrinsic/metric/sampled_field_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// Mean squared second difference of `f` read as an n1 × n2 grid, index i + n1·j (i fastest), along both axes.
double roughness(const std::vector<double>& f, int n1, int n2) {
  double sum = 0;
  long long terms = 0;
  for (int j = 0; j < n2; ++j)
    for (int i = 0; i < n1; ++i) {
      const double c = f[static_cast<size_t>(j) * n1 + i];
      if (i > 0 && i + 1 < n1) {
        const double d = f[static_cast<size_t>(j) * n1 + i - 1] - 2 * c + f[static_cast<size_t>(j) * n1 + i + 1];
        sum += d * d, ++terms;
      }
      if (j > 0 && j + 1 < n2) {
        const double d = f[static_cast<size_t>(j - 1) * n1 + i] - 2 * c + f[static_cast<size_t>(j + 1) * n1 + i];
        sum += d * d, ++terms;
      }
    }
  return terms > 0 ? sum / static_cast<double>(terms) : 0.0;
}

// Σ_i √g_uu(i, j) Δu: the length of the circle v = v_j to first order (g_uv ignored: it only lengthens the circle).
double circleLength(const SampledField& f, int j) {
  const double du = (f.domain.u1 - f.domain.u0) / f.nu;
  double c = 0;
  for (int i = 0; i < f.nu; ++i) c += std::sqrt(std::max(0.0, f.guu[static_cast<size_t>(j) * f.nu + i])) * du;
  return c;
}

const char* kPoleConvention =
    "with `poles both`, u must be phi (the periodic longitude, 0 to 2pi) and v theta (the colatitude, 0 to pi, "
    "0 at a pole)";

// The regular form at the pole next to row `row` (0 or NV-1): per u, the mean of the samples at u and u + π (the
// points at distance h/2 on either side of the pole along one great circle), divided by sin v and sin²v.
void checkOnePole(const SampledField& f, int row, const char* name) {
  const double s = std::sin(f.nodeV(row));
  double meanA = 0, meanE = 0, minTrace = std::numeric_limits<double>::infinity(), maxTrace = -minTrace;
  for (int i = 0; i < f.nu; ++i) {
    const size_t k = static_cast<size_t>(row) * f.nu + i, q = static_cast<size_t>(row) * f.nu + (i + f.nu / 2) % f.nu;
    const double A = 0.5 * (f.guu[k] + f.guu[q]) / (s * s), B = 0.5 * (f.guv[k] + f.guv[q]) / s,
                 E = 0.5 * (f.gvv[k] + f.gvv[q]);
    if (!std::isfinite(A) || !std::isfinite(B) || !std::isfinite(E) || !(A > 0) || !(A * E - B * B > 0))
      throw InputError(f.source + ": at the pole " + name + " the regular form (g_uu/sin^2 v, g_uv/sin v, g_vv) = (" +
                       num(A) + ", " + num(B) + ", " + num(E) + ") at u node " + std::to_string(i) +
                       " is not finite and positive definite; " + kPoleConvention);
    meanA += A / f.nu, meanE += E / f.nu;
    minTrace = std::min(minTrace, A + E), maxTrace = std::max(maxTrace, A + E);
  }
  const double meanTrace = meanA + meanE;
  if (maxTrace - meanTrace > kPoleVariationBound * meanTrace || meanTrace - minTrace > kPoleVariationBound * meanTrace)
    throw InputError(f.source + ": at the pole " + name + " the trace g_uu/sin^2 v + g_vv of the regular form varies "
                     "along u from " + num(minTrace) + " to " + num(maxTrace) + " (a smooth pole has it constant; " +
                     "accepted within " + num(100 * kPoleVariationBound) + " % of its mean " + num(meanTrace) +
                     "): is the grid transposed? The format wants u varying fastest (line k = j*NU + i is node (i, j)); " +
                     kPoleConvention);
  const double ratio = meanA / meanE;
  if (!(ratio <= kPoleRatioBound && ratio >= 1 / kPoleRatioBound))
    throw InputError(f.source + ": at the pole " + name + " the mean of g_uu/sin^2 v is " + num(meanA) +
                     " but the mean of g_vv is " + num(meanE) + " (ratio " + num(ratio) +
                     "; a smooth pole has them equal, accepted within a factor " + num(kPoleRatioBound) + "): " +
                     kPoleConvention + ". Are g_uu and g_vv swapped (theta-theta listed first)?");
}

}  // namespace

void checkFieldGridOrder(const SampledField& f) {
  if (f.nu == f.nv || f.nu < 3 || f.nv < 3) return;
  const size_t n = static_cast<size_t>(f.nu) * f.nv;
  if (f.guu.size() != n || f.guv.size() != n || f.gvv.size() != n) return;  // the shape check names this
  double asGiven = 0, transposed = 0;
  for (const std::vector<double>* c : {&f.guu, &f.guv, &f.gvv}) {
    asGiven += roughness(*c, f.nu, f.nv);
    transposed += roughness(*c, f.nv, f.nu);
  }
  if (!std::isfinite(asGiven) || !std::isfinite(transposed)) return;  // the finiteness check names the sample
  if (asGiven > kTransposedRoughness * transposed)
    throw InputError(f.source + ": the samples look transposed: read u fastest (as the format says, grid " +
                     std::to_string(f.nu) + " x " + std::to_string(f.nv) + ") they are " + num(asGiven / transposed) +
                     " times rougher (mean squared second difference) than read v fastest; write the data with u "
                     "varying fastest (line k = j*NU + i is node (i, j)), or swap NU and NV and the chart's axes");
}

void checkFieldPoles(const SampledField& f) {
  const ChartDomain& d = f.domain;
  const size_t n = static_cast<size_t>(f.nu) * f.nv;
  if (f.guu.size() != n || f.guv.size() != n || f.gvv.size() != n || f.nv < 2) return;
  if (d.poleAtV0 && d.poleAtV1) {
    if (f.nu % 2 != 0) return;  // SampledMetric names the odd NU
    checkOnePole(f, 0, "v = 0");
    checkOnePole(f, f.nv - 1, "v = pi");
    return;
  }
  if (!d.periodicU || d.periodicV || d.poleAtV0 || d.poleAtV1) return;
  for (int end = 0; end < 2; ++end) {
    const int row = end == 0 ? 0 : f.nv - 1, next = end == 0 ? 1 : f.nv - 2;
    const double cEnd = circleLength(f, row), cNext = circleLength(f, next);
    if (std::isfinite(cNext) && 2 * cEnd < cNext)
      throw InputError(f.source + ": the circles v = const shrink to a point at v = " + num(end ? d.v1 : d.v0) +
                       " (length " + num(cEnd) + " on the end row, " + num(cNext) +
                       " on the next: zero within one grid step beyond the chart): is this a sphere? add `poles both` "
                       "(u = phi in 0 2pi, v = theta in 0 pi, v-nodes cell-centred (j + 1/2) pi/NV); a genuine annulus "
                       "needs a grid that resolves its end circle");
  }
}

}  // namespace conformesh::intrinsic
