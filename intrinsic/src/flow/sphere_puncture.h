// sphere_puncture.h (private) — the genus-0 target of uniformize: puncture a vertex ∞, solve the flat Dirichlet
// problem on the rest, repair the star of ∞ by Ptolemy flips until its link is convex, lay the disk out in the plane,
// map it to the unit sphere by inverse stereographic projection, centre it by Möbius maps and check the spherical
// triangulation. Reads the input; writes only the Uniformization and report it is given. docs/ricci_flow.md §3.1
// and "Uniformization targets and the genus-0 puncture" derive each step.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::intrinsic::detail {

// Closed genus-0 `input` → the unit sphere: tries up to options.maxPunctureAttempts puncture candidates (simple stars,
// most uniform spokes first). `report` carries genus and loops in; the result's report adds the sphere's fields.
// Throws InputError when no vertex has a simple star, ConvergenceError (every attempt's reason) when all fail.
Uniformization uniformizeSphere(const IntrinsicTriangulation& input, const UniformizationOptions& options,
                                UniformizationReport report);

// Outcome of one puncture: ok, or why it was rejected (a progress line and part of the final error).
struct SphereAttempt {
  bool ok = false;
  std::string why;
};

// One puncture attempt at vertex `puncture`. run() performs the steps in order; each step that can fail returns a
// rejected SphereAttempt. `report` (the attempt's) gains the flow counts, centring iterations and pennerLengths.
class SpherePuncture {
 public:
  SpherePuncture(const IntrinsicTriangulation& input, const UniformizationOptions& options, int puncture,
                 UniformizationReport& report);
  SpherePuncture(const SpherePuncture&) = delete;
  SpherePuncture& operator=(const SpherePuncture&) = delete;

  // On success fills out.uniform (spherical lengths), out.positions (unit vectors), λ and the correspondence.
  SphereAttempt run(Uniformization& out);

 private:
  // Steps 1–4 (docs/ricci_flow.md, "the puncture, step by step"): the flat Dirichlet problem and the star of ∞.
  void setInitialGuess();              // u_v = −2 log d(v, ∞), d the edge-path distance
  bool updateStar();                   // star, link and Dirichlet values after flips; false: link not simple
  void configureFlow();                // stall returns, one shared factor, stops at clearly reflex link vertices
  SphereAttempt solveAndRepairStar();  // solve, repair, repeat until a round changes nothing
  bool flipDegenerateFacesIntoStar();  // repair (i): a disk face degenerate against the link joins the star
  bool releaseReflexLinkVertices(const RicciFlowReport& solved);  // repair (ii): reflex link vertices leave
  void reportRepairRound(int round, const RicciFlowReport& solved) const;
  bool clearlyReflex(int a, const std::vector<double>& sums, double maxResidual) const;
  double diskAngleSumAt(int a) const;    // Θ_a over the non-frozen faces, extension (π, 0, 0) of degenerate ones
  void solveVertexLocally(int a);        // Θ_a(u_a) = 2π by bisection, neighbours fixed
  SphereAttempt checkDiskFaces() const;  // every non-frozen face a valid triangle

  // Steps 5–7: map back to the sphere and check.
  SphereAttempt layOutDisk();  // planar layout of the disk, every edge checked (edgeLaidOut)
  bool edgeLaidOut(int h) const;
  void projectToSphere();             // centre, scale, inverse stereographic projection; w of ∞
  void centreByMobius();              // Newton on the area centroid by Möbius maps of the ball
  void setSphericalLengths();         // chords of the points, or the Penner form for every edge
  SphereAttempt checkSphere() const;  // valid positively oriented faces, angle sums 2π
  std::vector<double> sphericalAngleSums() const;

  const IntrinsicTriangulation& input_;
  const UniformizationOptions& options_;
  const int inf_;  // the puncture ∞
  UniformizationReport& report_;
  DiscreteConformalMetric metric_;
  const HalfedgeMesh& m_;  // metric_'s connectivity (changes with its flips)
  FlowCorrespondence log_;
  const int nV_;

  ConformalTarget target_;         // 2π everywhere; fixed: ∞ and its link (Dirichlet)
  std::vector<char> frozen_;       // per face: in the star of ∞
  std::vector<int> link_;          // the link of ∞ in rotation order
  std::vector<int> released_;      // link vertices released in the current round
  std::vector<char> judgedEarly_;  // per vertex: judged clearly reflex before a solution once already
  RicciFlowOptions flow_;

  std::vector<double> spoke_;         // reference chords c_a∞ in link order, after the repairs
  IntrinsicTriangulation planarTri_;  // the flat disk (star of ∞ frozen, not laid out)
  std::vector<Eigen::Vector2d> z_;    // its layout
  double allowance_ = 0;              // edgeLaidOut's tolerance relative to the coordinates
  std::vector<double> w_;             // total vertex scaling (log of the length factor)
  std::vector<Eigen::Vector3d> x_;    // points on the unit sphere
  IntrinsicTriangulation sphere_;     // the spherical triangulation
  std::vector<char> fromPoints_;      // per edge: its chord resolved (≥ 10⁻⁴)
};

}  // namespace conformesh::intrinsic::detail
