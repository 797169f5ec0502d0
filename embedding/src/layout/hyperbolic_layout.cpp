// hyperbolic_layout.cpp — deck group of a developed hyperbolic surface in SU(1,1) and its relation. See
// hyperbolic_layout.h and docs/layout.md §4.
#include "conformesh/embedding/layout/hyperbolic_layout.h"

#include <cmath>

#include <Eigen/LU>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

HyperbolicLayout layoutHyperbolic(const intrinsic::IntrinsicTriangulation& tri,
                                  const FundamentalDomainOptions& options) {
  if (tri.background != intrinsic::Background::Hyperbolic)
    throw InputError("layoutHyperbolic: expected a hyperbolic triangulation, found background " +
                     intrinsic::toString(tri.background));
  HyperbolicLayout h;
  h.domain = developFundamentalDomain(tri, options);
  if (h.domain.basis.genus < 2)
    throw InputError("layoutHyperbolic: expected genus >= 2, found genus " + std::to_string(h.domain.basis.genus));
  for (const Mobius& m : h.domain.generators) {
    DeckGenerator g;
    g.matrix = m;
    const Complex a = m(0, 0);
    g.translationLength = 2 * std::acosh(std::max(1.0, std::abs(a.real())));
    h.maxDeterminantError = std::max({h.maxDeterminantError, std::abs(m.determinant() - 1.0),
                                      std::abs(m(1, 1) - std::conj(a)), std::abs(m(1, 0) - std::conj(m(0, 1)))});
    h.generators.push_back(g);
  }
  h.relation = toString(h.domain.basis.relation);
  h.relationResidual = h.domain.relationResidual;
  return h;
}

std::vector<Mobius> deckWords(const std::vector<Mobius>& generators, int maxLength) {
  std::vector<Mobius> out{Mobius::Identity()};
  std::vector<std::pair<Mobius, int>> frontier{{Mobius::Identity(), 0}};  // (element, last letter)
  const int n = static_cast<int>(generators.size());
  for (int length = 1; length <= maxLength; ++length) {
    std::vector<std::pair<Mobius, int>> next;
    for (const auto& [element, last] : frontier)
      for (int i = 1; i <= n; ++i)
        for (int s : {i, -i}) {
          if (s == -last) continue;  // reduced words only
          const Mobius g = s > 0 ? generators[i - 1] : Mobius(generators[i - 1].inverse());
          next.emplace_back(element * g, s);
          out.push_back(next.back().first);
        }
    frontier = std::move(next);
  }
  return out;
}

}  // namespace conformesh::embedding
