// refiner.h — the state and the steps of refineDelaunay (delaunay_refinement.h), internal to conformesh_refine.
// One Refiner runs once: it copies the input triangulation and refines the copy in place, with its queues, boundary
// data, statistics and work buffers as members. Its methods live in three files:
//   delaunay_refinement.cpp — the loop: setup, the queues, processSegment / processFace and the steps of a bad face;
//   refiner_insertion.cpp   — the mutations: Lawson flips, face / edge / segment splits with signposts and locations;
//   refiner_boundary.cpp    — boundary circles, encroachment tests and Chew's deletion of free vertices.
// It touches only its own copy (RefineResult) and reads the input and the options.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/input_location.h"

namespace conformesh::refine::detail {

// x with 6 significant digits, for error messages.
std::string num(double x);

// Circumradius of face f (+∞ for a degenerate face or a hyperbolic triangle without a circumcircle). Euclidean: abc /
// (4·area) with Kahan's area, cheaper than intrinsic::faceCircumradius and equal to it up to round-off.
double circumradiusOf(const intrinsic::IntrinsicTriangulation& tri, int f);

// One boundary loop: whether it is split on its circle, the circle's radius, and on which side of the loop's halfedges
// (interior on their left) the centre lies: left for an outer loop, right for a hole of a circle domain.
struct LoopCircle {
  bool circle = false;
  double radius = 0;
  bool centerOnLeft = true;
};

// What processFace knows about a queued face: its figures, and (once it is known to need work) its layout from the
// corner opposite its longest edge, where traces start.
struct BadFace {
  int face = intrinsic::kInvalid;
  double shortest = 0, R = 0;  // shortest edge, circumradius (+∞ without a circumcircle)
  int longestK = 0;            // the longest edge is 3·face + longestK
  bool badShape = false, mayBeBadSize = false;
  int hs = intrinsic::kInvalid, v = intrinsic::kInvalid;  // the halfedge traces start along, and its tail
  std::array<Vec3, 3> P;                                  // layoutAtHalfedge(hs)
  std::optional<Vec3> cc;                                 // circumcentre in that layout
  bool centroid = false;                                  // no circumcircle: split at the centroid
};

// A located point: the trace to it in the refined triangulation and the follow-up on the input.
struct LocatedPoint {
  TraceResult trace;
  InputSurface::Arrival arrival;
  bool frontal = false;  // Rebay's frontal point rather than the circumcentre / off-centre / centroid
};

class Refiner {
 public:
  Refiner(const intrinsic::IntrinsicTriangulation& input, const RefineOptions& options)
      : in_(input), opt_(options), model_(input.background) {}

  RefineResult run();

 private:
  // === setup (delaunay_refinement.cpp, refiner_boundary.cpp)
  void validate();
  void initialize();
  void setupBoundary();
  LoopCircle fitLoopCircle(int loopIndex, const std::vector<int>& loop, const std::vector<double>& angleSums);
  // === queues and tests
  void pushFace(int f);
  void pushFacesAround(int v);
  double meanLambda(int f) const;
  bool meetsSizeTarget(int f) const;
  void pushFront(int f);
  bool segmentEncroached(int e) const;
  void processSegment(int e);
  // === a bad face, step by step (delaunay_refinement.cpp)
  void processFace(int f);
  BadFace examineFace(int f) const;
  void layOutFace(BadFace& b) const;
  bool offCenterPoint(const BadFace& b, Vec3& target) const;
  void requireAboveSmallestSize(const BadFace& b) const;
  std::optional<Vec3> frontalPoint(int f, const std::array<Vec3, 3>& P, const Vec3& c) const;
  TraceResult traceToward(const BadFace& b, const Vec3& x, double& theta, double& r);
  InputSurface::Arrival followOnInput(const BadFace& b, double theta, double r) const;
  bool sizeBadAt(const BadFace& b, const InputSurface::Arrival& arrival) const;
  void moveToFrontalPoint(const BadFace& b, const Vec3& front, LocatedPoint& x);
  void rejectAtSegment(int f, int e);
  bool splitSegmentsEncroachedBy(int f, const TraceResult& trace);
  void countInsertionKind(const BadFace& b, bool offCenter, bool frontal);
  // === mutation (refiner_insertion.cpp)
  void flip(int e);
  void restoreDelaunay(std::vector<int>& stack, int center = intrinsic::kInvalid);  // consumes `stack`
  int delaunaySign(int e) const;
  bool sphericalBothAcute(int e) const;  // delaunaySign's filter in the spherical background
  void afterInsertion(int p);
  void appendVertexData(const InputLocation& location);
  void splitSegment(int e);
  Vec3 segmentSplitPoint(int e, const LoopCircle& lc) const;  // arc midpoint, shell point or geodesic midpoint
  void insertAt(const TraceResult& trace, const InputSurface::Arrival& arrival);
  void insertOnEdge(const TraceResult& trace, int cornerOpposite);
  // Where point t of trace.face's layout lies on the input: the geodesic from the face's corner j to t, followed there.
  InputSurface::Arrival followOnInputTo(const TraceResult& trace, int j, const Vec3& t) const;
  void countInsertion();
  // === boundary tests and Chew's deletions (refiner_boundary.cpp)
  std::vector<int> encroachedByPoint(const TraceResult& trace) const;
  // SegmentRule::Chew: the free vertices strictly inside the diametral disk of boundary edge e, and their deletion
  // before e is split; returns e's index afterwards (removal compacts the edge array).
  std::vector<int> freeVerticesInDiametralDisk(int e) const;
  int deleteFreeVertices(int e);
  void followCompaction(const intrinsic::ElementMoves& moves, int mergedFace);  // after a vertex removal
  // === the loop. drain() serves the queues until they are empty; drainAll() first Lawson-flips every edge and queues
  // every face and boundary segment (the start, and the restart after a smoothing pass).
  void drain();
  void drainAll();
  void smoothAndRefine();

  const intrinsic::IntrinsicTriangulation& in_;
  RefineOptions opt_;
  BackgroundModel model_;
  std::optional<InputSurface> inputStore_;  // built after validation
  const InputSurface* inputPtr_ = nullptr;
  RefineResult res_;
  intrinsic::IntrinsicTriangulation& tri_ = res_.triangulation;
  Signposts& sp_ = res_.signposts;
  std::vector<int> edgeLoop_;  // per edge: boundary loop index, −1 for interior edges
  std::vector<LoopCircle> loops_;
  std::vector<char> sharpCorner_;  // per vertex: an input boundary vertex whose angle is below 60°
  bool hasBoundary_ = false, uniform_ = true;
  double lambdaMax_ = 0, minSize_ = 0;
  // Bad-triangle candidates, largest relative size R·e^λ first (λ averaged over the corners): refining from the
  // coarse end, as Triangle does, spreads insertions evenly and gives better-shaped meshes than first-in-first-out
  // (docs/refinement.md §1). Keys may go stale when flips change a queued face; they only order the work,
  // processFace re-tests every face.
  std::priority_queue<std::pair<double, int>> faceQueue_;
  // With RefineOptions::frontal: the bad faces next to a face that meets its size target (the front), served before
  // faceQueue_ so that the mesh grows from good regions as in Rebay's algorithm. Entries may go stale; processFace
  // re-tests every face, and every bad face is also in faceQueue_.
  std::priority_queue<std::pair<double, int>> frontQueue_;
  std::vector<char> frontQueued_;
  std::deque<int> segmentQueue_;
  std::vector<char> faceQueued_;
  // Reused work buffers (no allocation per insertion): the cavity search of encroachedByPoint, Lawson's edge stack.
  mutable std::vector<std::pair<int, std::array<Vec3, 3>>> cavityStack_;
  mutable std::vector<int> cavityVisited_;
  std::vector<int> flipStack_;
  std::int64_t insertions_ = 0;
  std::chrono::steady_clock::time_point lastProgress_ = std::chrono::steady_clock::now();
};

}  // namespace conformesh::refine::detail
