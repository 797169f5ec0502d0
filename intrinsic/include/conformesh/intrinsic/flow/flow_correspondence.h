// flow_correspondence.h — which point of the input triangulation T0 each point of the uniformized triangulation T0*
// is, across the vertex scaling and the Ptolemy flips the discrete Ricci flow performed: a log of the flips (with their
// reference Penner lengths) and the per-vertex log scale, replayed to map points either way. The map is a
// piecewise-projective homeomorphism, K-quasi-conformal as the paper's Remark 1 needs.
//
// Pure data and maps: touches nothing but its own log. The model (decorated ideal triangles, light-like vectors of
// R^{2,1}) and the replay: docs/ricci_flow.md §5.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "conformesh/intrinsic/mesh/halfedge_mesh.h"

namespace conformesh::intrinsic {

// A point on a triangulation: face and barycentric coordinates, bary[k] belonging to faceVertex(face, k). For
// spherical and hyperbolic faces the coordinates are those of the chord triangle (the flat triangle spanned by the
// three vertices on the unit sphere, resp. on the hyperboloid), whose central projection to the surface is the
// gnomonic resp. Klein (projective) model of the face: geodesics are straight.
struct FacePoint {
  int face = 0;
  std::array<double, 3> bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
};

// One Ptolemy flip of edge ab with quad faces fa = (a, b, c) and fb = (b, a, d), a at corner `cornerA` of fa and b at
// corner `cornerB` of fb before the flip; afterwards fa = (d, c, a) and fb = (c, d, b) at corners 0, 1, 2 (the
// convention of HalfedgeMesh::flip). Lengths are Penner lengths in the reference decoration (u = 0) of the input.
struct PtolemyFlip {
  int faceA = 0, faceB = 0;
  std::uint8_t cornerA = 0, cornerB = 0;
  double ab = 0, bc = 0, ca = 0, ad = 0, db = 0, cd = 0;
};

class FlowCorrespondence {
 public:
  FlowCorrespondence() = default;
  explicit FlowCorrespondence(int nFaces) : nFaces_(nFaces) {}

  void recordFlip(const PtolemyFlip& flip) { flips_.push_back(flip); }
  // Discards the flips recorded after the first `count` (used when a puncture vertex is rejected and the flow
  // restarts).
  void truncate(std::size_t count) { flips_.resize(count); }
  const std::vector<PtolemyFlip>& flips() const { return flips_; }
  int nFaces() const { return nFaces_; }

  // Per vertex of T0*: its Penner lengths are e^{(w_i+w_j)/2} times the reference Penner lengths of the same edge.
  std::vector<double> logScale;

  // Maps points of T0* (connectivity `uniformMesh`, the mesh the flow returned) to T0, all together:
  // O(#flips + #points + #faces) plus the work of moving points that sit in flipped quads. Throws InputError naming
  // the point for a face out of range or coordinates that are not finite, non-negative (to −1e-9) and summing to 1
  // (to 1e-9).
  std::vector<FacePoint> mapToInput(const HalfedgeMesh& uniformMesh,
                                    const std::vector<FacePoint>& pointsOnUniform) const;

  // The inverse direction, T0 → T0* (replays the log forwards, then applies the rescaling).
  std::vector<FacePoint> mapToUniform(const HalfedgeMesh& uniformMesh,
                                      const std::vector<FacePoint>& pointsOnInput) const;

 private:
  int nFaces_ = 0;
  std::vector<PtolemyFlip> flips_;
};

}  // namespace conformesh::intrinsic
