// convergence_order.h — the order of convergence measured as the least-squares slope of log y against log x, the way
// every convergence claim in conformesh is checked (error against mesh size, over several resolutions).
#pragma once

#include <vector>

namespace conformesh::intrinsic {

// Least-squares slope of log y against log x. Throws InputError for fewer than two points, sizes that differ, or a
// value that is not positive (naming the point).
double fitLogLogSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace conformesh::intrinsic
