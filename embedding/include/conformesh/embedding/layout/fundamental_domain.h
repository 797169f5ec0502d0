// fundamental_domain.h — the developing map of a closed flat or hyperbolic triangulation cut along T ∪ G
// (homology_basis.h): the faces are unfolded across the cotree C into the plane C (flat) or the Poincaré disk
// (hyperbolic), and each cut halfedge gets the deck transformation A_h that carries the developed disk D onto its
// neighbouring tile across h. Isometries are stored as 2×2 complex matrices acting by Möbius transformations:
// [[α, β], [0, 1]] with |α| = 1 (z ↦ αz + β) in the plane, SU(1,1) = [[a, b], [b̄, ā]], |a|² − |b|² = 1 on the disk.
//
// Faces are placed by composing per-edge transition matrices built from lengths and angles (never by re-intersecting
// circles), in long double, so a face at depth k of the cotree carries k products of 10⁻¹⁹ round-off. docs/layout.md §2
// derives the formulas.
#pragma once

#include <array>
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/layout/homology_basis.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::embedding {

using Complex = std::complex<double>;
using Mobius = Eigen::Matrix<Complex, 2, 2>;

Complex applyMobius(const Mobius& m, Complex z);
// The Möbius transformation of the product M1 M2 ⋯ over a word (letter ±(i+1) = generators[i]^{±1}).
Mobius evaluateWord(const std::vector<Mobius>& generators, const GroupWord& word);
// Distance of m from the identity of PSU(1,1) resp. the Euclidean group: min(‖m − I‖, ‖m + I‖) (max-entry norm) after
// scaling m to determinant 1.
double distanceFromIdentity(const Mobius& m);

struct FundamentalDomainOptions {
  // Apply one final isometry so that the developed disk is centred: its area-weighted vertex centroid at 0 (flat), or
  // the hyperboloid barycentre of its corners at the disk's centre (hyperbolic), with corner 0 of the root face on +x.
  bool centre = true;
};

struct FundamentalDomain {
  intrinsic::Background background = intrinsic::Background::Euclidean;
  HomologyBasis basis;
  std::vector<std::array<Complex, 3>> corners;  // per face: its three corners in the developed disk D
  std::vector<Mobius> faceMap;                  // per face: standard placement → D (see docs/layout.md §2)
  std::vector<Mobius> crossing;                 // per halfedge: A_h (identity for cotree halfedges)
  std::vector<Mobius> generators;               // A_h of the generator halfedges edgeHalfedge(e), e ∈ G, in order
  // distanceFromIdentity of the relation word evaluated on the generators (in long double, in D's frame).
  double relationResidual = 0;
  // Max over vertices of distanceFromIdentity of the transitions τ around the vertex composed in its own face frame
  // (= M⁻¹ (A_{x_0} ⋯ A_{x_{k−1}}) M): of the order of the vertex's angle-sum error.
  double maxVertexResidual = 0;
  double minSignedArea = 0;  // min over faces of the signed area of the developed corners (> 0: all positive)
};

// Develops a closed Euclidean or hyperbolic triangulation (e.g. intrinsic::uniformize's T0* of genus ≥ 1). Throws
// InputError for a spherical background, a surface with boundary, or an invalid face (naming it).
FundamentalDomain developFundamentalDomain(const intrinsic::IntrinsicTriangulation& tri,
                                           const FundamentalDomainOptions& options = {});

}  // namespace conformesh::embedding
