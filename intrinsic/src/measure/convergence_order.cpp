// convergence_order.cpp — least-squares order of convergence from a log–log fit (convergence_order.h).
#include "conformesh/intrinsic/measure/convergence_order.h"

#include <cmath>
#include <string>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

double fitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 2)
    throw InputError("log-log fit: need at least two (x, y) pairs of equal count, found " + std::to_string(x.size()) +
                     " and " + std::to_string(y.size()));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0))
      throw InputError("log-log fit: point " + std::to_string(i) + " (" + std::to_string(x[i]) + ", " +
                       std::to_string(y[i]) + ") is not positive");
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double n = static_cast<double>(x.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace conformesh::intrinsic
