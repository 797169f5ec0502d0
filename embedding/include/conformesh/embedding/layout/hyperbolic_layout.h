// hyperbolic_layout.h — a closed hyperbolic surface of genus g ≥ 2 (intrinsic::uniformize's T0*, curvature −1)
// developed into the Poincaré disk: the fundamental domain D (the surface cut along the tree–cotree graph), the 2g
// deck transformations of the generator loops as elements of SU(1,1) (Möbius maps z ↦ (az + b)/(b̄z + ā) of the disk,
// defined up to sign), and the check of the surface-group relation. docs/layout.md §4.
#pragma once

#include <string>
#include <vector>

#include "conformesh/embedding/layout/fundamental_domain.h"

namespace conformesh::embedding {

struct DeckGenerator {
  Mobius matrix;             // in SU(1,1), determinant 1
  double translationLength;  // 2 acosh(|Re a|): the length of the closed geodesic in the generator's free homotopy
                             // class (|trace| = 2|Re a| > 2 for every non-trivial element of a surface group)
};

struct HyperbolicLayout {
  FundamentalDomain domain;
  std::vector<DeckGenerator> generators;  // 2g, in HomologyBasis::generatorEdges order
  std::string relation;                   // the relation word, e.g. "g1 g2 g1^-1 g3 ..." (length 4g)
  double relationResidual = 0;            // distance of the evaluated relation from ±I
  double maxDeterminantError = 0;  // max |det − 1| and max |d − ā|, |c − b̄| over the generators (SU(1,1) form)
};

// Throws InputError for a surface that is not a closed hyperbolic triangulation of genus ≥ 2.
HyperbolicLayout layoutHyperbolic(const intrinsic::IntrinsicTriangulation& tri,
                                  const FundamentalDomainOptions& options = {});

// The images of the fundamental domain under all reduced words of length ≤ `maxLength` in the generators (the identity
// first): the tiles of the universal cover drawn by layout_picture.h.
std::vector<Mobius> deckWords(const std::vector<Mobius>& generators, int maxLength);

}  // namespace conformesh::embedding
