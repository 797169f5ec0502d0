// face_angles.h — per-face geometry of a vertex-scaling metric at its current u: edge lengths, corner angles and their
// cotangents, the angle sums, and ∂θ/∂u. Private to the flow (newton_flow.cpp, ricci_flow.cpp); reads the metric only.
#pragma once

#include <vector>

#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic::detail {

// The three side lengths, angles and angle cotangents of a face: L[k] is opposite corner k. A face violating the
// triangle inequality gets the angles (π, 0, 0), π opposite its longest side: the continuous extension of the angles
// that makes the energy C¹ and convex on all of u-space (Luo; Bobenko–Pinkall–Springborn 2015, §4). Such faces only
// occur next to unflippable (boundary, frozen) edges; interior ones are repaired by the Ptolemy flips.
struct FaceGeometry {
  double L[3], theta[3], cot[3];
  bool degenerate = false;
};

// The geometry of a face with sides L0, L1, L2 (L_k opposite corner k) in background bg, by the half-angle formulas
// of triangle_geometry.h (the same numbers as angleOpposite and cotOpposite).
FaceGeometry faceGeometry(Background bg, double L0, double L1, double L2);
// Face f of `metric` with the edge lengths `length`.
FaceGeometry faceGeometry(const DiscreteConformalMetric& metric, const std::vector<double>& length, int f);

// Current background length of every edge: ℓ(e^{(u_i+u_j)/2} c⁰_ij); `length` gets one entry per edge.
void currentLengths(const DiscreteConformalMetric& metric, std::vector<double>& length);

// Edge lengths, per-vertex angle sums over the non-frozen faces, and each non-frozen face's geometry (for the Jacobian
// at the same point). Bit for bit those of a serial run whatever the number of threads.
void evaluateFaces(const DiscreteConformalMetric& metric, std::vector<double>& length, std::vector<double>& sums,
                   std::vector<FaceGeometry>& faces);

// J[k][j] = ∂θ_k/∂u_{v_j} for the corners of a face (0 for a degenerate face: the extended angles are locally
// constant).
void angleJacobian(Background bg, const FaceGeometry& g, double J[3][3]);

// Σ over the non-frozen faces of Σ_k (α_k − π/2) λ_k + 2 Л(α_k), λ_k = 2 log L_k: the face part of conformalEnergy
// (conformal_energy.h) from faces evaluated at the current u; adds Σ |terms| + |λ_k| to `magnitude` (round-off scale).
double faceEnergy(const DiscreteConformalMetric& metric, const std::vector<FaceGeometry>& faces, double& magnitude);

}  // namespace conformesh::intrinsic::detail
