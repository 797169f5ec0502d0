// Tests for convergence_order.h: the least-squares log–log slope recovers exact power laws and names bad points.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/measure/convergence_order.h"

using namespace conformesh::intrinsic;

TEST_CASE("log–log fits recover exact power laws") {
  std::vector<double> x = {1, 2, 4, 8}, y;
  for (double xi : x) y.push_back(3 * std::pow(xi, -1.5));
  CHECK(fitLogLogSlope(x, y) == Approx(-1.5).epsilon(1e-12));
  REQUIRE_THROWS_WITH(fitLogLogSlope({1, 0}, {1, 1}), Catch::Contains("point 1"));
  REQUIRE_THROWS_WITH(fitLogLogSlope({1}, {1}), Catch::Contains("at least two"));
}
