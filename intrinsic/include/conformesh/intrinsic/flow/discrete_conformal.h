// discrete_conformal.h — discrete conformal metrics by vertex scaling, kept in Penner coordinates: a connectivity,
// reference Penner (chord) lengths c⁰ and a conformal factor u per vertex, c_ij = e^{(u_i+u_j)/2} c⁰_ij, with Ptolemy
// flips c_cd = (c_ad c_bc + c_db c_ca)/c_ab that keep every u admissible (Gu–Luo–Sun–Wu 2018; Gu–Guo–Luo–Sun–Wu for
// the hyperbolic case).
//
// A DiscreteConformalMetric owns its triangulation; flips change only it and the correspondence log they are given.
// Background lengths from chords, and why Ptolemy flips are exact: docs/ricci_flow.md §1.
#pragma once

#include <cstdint>
#include <vector>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// ℓ from the Penner (chord) length c in background g, and back.
double lengthFromPenner(Background g, double c);
double pennerFromLength(Background g, double length);

// ∂ℓ_ij/∂u_i of a vertex-scaled edge of length ℓ: ℓ/2 (Euclidean), tanh(ℓ/2) (hyperbolic), tan(ℓ/2) (spherical).
double lengthDerivativeInU(Background g, double length);

// Penner-coordinate Delaunay test of interior edge ab with triangles (a, b, c), (b, a, d), from Penner lengths:
// (c_bc² + c_ca² − c_ab²)/(c_bc c_ca) + (c_ad² + c_db² − c_ab²)/(c_ad c_db) = 2(cos γ_c + cos γ_d), non-negative iff
// the edge is Delaunay. Defined for any positive lengths, also ones violating the triangle inequality
// (docs/ricci_flow.md §1).
double pennerDelaunayMargin(double ab, double bc, double ca, double ad, double db);

class DiscreteConformalMetric {
 public:
  // `reference` gives the connectivity and the reference Penner lengths c⁰ (u = 0); `geometry` the background in which
  // lengths are read. Faces marked frozen are never flipped and their edges keep their connectivity (the puncture's
  // star in the genus-0 construction); an edge is flippable iff it is interior and both its faces are not frozen.
  DiscreteConformalMetric(IntrinsicTriangulation reference, Background geometry);

  const HalfedgeMesh& mesh() const { return tri_.mesh; }
  Background geometry() const { return geometry_; }
  int nVertices() const { return tri_.mesh.nVertices(); }

  std::vector<double>& u() { return u_; }
  const std::vector<double>& u() const { return u_; }
  void setFrozenFaces(std::vector<char> frozen) { frozen_ = std::move(frozen); }
  bool isFrozen(int f) const { return !frozen_.empty() && frozen_[f]; }

  double referencePenner(int e) const { return tri_.edgeLengths[e]; }
  const std::vector<double>& referencePennerLengths() const { return tri_.edgeLengths; }
  // Current Penner length and background length of edge e.
  double penner(int e) const;
  double length(int e) const { return lengthFromPenner(geometry_, penner(e)); }

  // Lawson flipping with Ptolemy lengths until every flippable edge has pennerDelaunayMargin ≥ −tolerance at the
  // current u. Each flip is appended to `log` (may be null). Returns the number of flips. Terminates for every u (the
  // Penner flip algorithm decreases the Epstein–Penner convex hull height), so the cap of 1000 flips per edge only
  // guards against non-finite u: hitting it throws ConvergenceError.
  std::int64_t makeDelaunay(double tolerance, FlowCorrespondence* log);

  // One Ptolemy flip of interior edge e regardless of frozen faces (the genus-0 construction flips edges of the
  // puncture's star itself); appended to `log`. Returns false for a boundary edge or one whose two sides are one face.
  bool flipPtolemy(int e, FlowCorrespondence* log);

  // The current metric as a triangulation in the background geometry.
  IntrinsicTriangulation triangulation() const;
  // True when every non-frozen face satisfies the strict triangle inequality of the background.
  bool allFacesValid() const;

 private:
  IntrinsicTriangulation tri_;  // edgeLengths hold the reference Penner lengths c⁰
  Background geometry_;
  std::vector<double> u_;
  std::vector<char> frozen_;
};

}  // namespace conformesh::intrinsic
