// pull_back.h — the mesh pipeline's pull-back (internal header of mesh_remesh.cpp): the refined T1* of the uniformized
// input T0* taken back through the input faces — vertices through the flow's correspondence, each edge traced across
// T0* (geodesic_trace.h), its pieces mapped to T0, bisected until resolved (image_path.h) and developed into the plane
// for its length — and the checks of a result against its vertices' places on T0, shared by both routes.
// Derivation: docs/refinement.md, "Mesh pull-back".
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "pipeline/image_path.h"

namespace conformesh::refine::detail {

// T0: the input, midpoint-subdivided 0 or more times (the same flat surface), with each face's place in the input.
struct SubdividedInput {
  intrinsic::IntrinsicTriangulation t0;
  std::vector<int> parentFace;                               // per T0 face: the input face it lies in
  std::vector<std::array<Eigen::Vector3d, 3>> parentCorner;  // per T0 face: its corners in that face's coordinates
};

// Pulls the refinement `refined` of u.uniform (T0*) back onto `input.t0`. run() fills, of `out`: location, lambda,
// edgePieces, pathPieces, inputEdgeCrossings, pathLength, maxBendExcess, notices (fold flips) and mesh (T1: Euclidean,
// developed lengths, validated). Throws ConvergenceError naming the output edge when a trace, a bisection (60 rounds)
// or a development fails on a degenerate input.
class ImagePathPullBack {
 public:
  ImagePathPullBack(const SubdividedInput& input, const intrinsic::Uniformization& u, const RefineResult& refined,
                    int extraBisections);
  void run(MeshRemeshResult& out);
  const std::vector<Point>& vertexImage() const { return vertexImage_; }  // per output vertex, its point on T0

 private:
  // A straight piece of an output edge inside one T0* face, and its ends' images on T0.
  struct Piece {
    int edge = 0;
    int starFace = 0;
    Eigen::Vector3d a, b;  // on T0*, coordinates of starFace
    Point imageA, imageB;  // on T0
    int depth = 0;         // bisections so far
    int order = 0;         // index of the traced piece it comes from (pieces of an edge are traced in path order)
    double t = 0;          // where it starts on that piece, as a fraction of it
  };
  struct Record {  // a resolved piece, in path order by (order, t)
    int edge, order;
    double t;
    Resolved r;
  };

  // A rigid motion of the plane, x ↦ R x + t.
  struct PlaneMotion {
    Eigen::Matrix2d R = Eigen::Matrix2d::Identity();
    Eigen::Vector2d t = Eigen::Vector2d::Zero();
    Eigen::Vector2d operator()(const Eigen::Vector2d& x) const { return R * x + t; }
    PlaneMotion inverse() const { return {R.transpose(), -(R.transpose() * t)}; }
    PlaneMotion operator*(const PlaneMotion& o) const { return {R * o.R, R * o.t + t}; }  // this after o
  };
  // An output edge developed from its end `tail`: chart(v) is the canonical layout (Development::start) of the T0
  // face of v's image for an inserted vertex; for an input vertex (a cone point), whatever chart the development
  // started or ended in (never composed through). pa, pb: the tail's and the other end's images in chart(tail);
  // motion: chart(other end) → chart(tail). ok: false when a development step failed (the edge is never flipped).
  struct EdgeChart {
    int tail = intrinsic::kInvalid;
    PlaneMotion motion;
    Eigen::Vector2d pa = Eigen::Vector2d::Zero(), pb = Eigen::Vector2d::Zero();
    bool ok = false;
  };

  void mapVertices(MeshRemeshResult& out);
  void placeInnerArcsOnChords();
  void traceEdges();
  void traceEdge(int e, std::vector<EdgeCrossing>& crossings);
  void mapPieceEnds();
  void resolvePieces(MeshRemeshResult& out);
  std::vector<Piece> bisect(const std::vector<Piece>& unresolved) const;
  std::vector<double> developLengths(MeshRemeshResult& out);
  EdgeChart chartOf(int edge, int startFace, const Eigen::Vector2d& from, const Development& end,
                    const Eigen::Vector3d& at) const;
  int untangleFolds(MeshRemeshResult& out);

  const SubdividedInput& input_;
  const intrinsic::Uniformization& u_;
  const RefineResult& refined_;
  const int extraBisections_;
  const int n0_;                    // T0's vertices: output vertices 0 .. n0−1
  const Signposts inputSignposts_;  // initialSignposts(T0*): the frame of T1*'s signposts at input vertices
  const BackgroundModel model_;
  std::vector<Point> vertexImage_;
  std::vector<Piece> pieces_;
  std::vector<int> firstPiece_;  // per output edge, its first piece; one past the end for the last
  std::vector<Record> records_;
  std::vector<double> pathLength_;
  std::vector<EdgeChart> charts_;  // per output edge
};

// Whether output edge `edge` may be pictured as the straight segment of its located ends inside T0 face `face`. Two
// corners of one input face need not be joined by that face's side: an intrinsic Delaunay edge between them may be
// another geodesic, around a cone vertex of angle below π (femur.off: vertex 1470, 128°). Empty: every edge may.
using EdgeInFace = std::function<bool(int edge, int face)>;

// The input route's EdgeInFace: an output edge with an end at input vertex v lies in face f only when its signpost
// direction at v (refined.signposts, in the frame of initialSignposts(input)) lies in f's corner wedge at v, to
// 1e-9 rad (flips re-derive signposts with ~1e-15 rad round-off; the wedges of distinct sides differ by corner angles,
// above 1e-6 rad on any mesh the reader accepts).
EdgeInFace signpostEdgeInFace(const intrinsic::IntrinsicTriangulation& input, const RefineResult& refined);

// Orientation of the output triangles on T0 and the same-face length check (MeshRemeshResult: invertedTriangles,
// orientationChecked, sameFaceEdges, maxSameFaceLengthError, loopEdges and the first offending elements), from the
// output vertices' points on T0. A triangle is checked in a face only when its three edges may lie in it (inFace).
void checkAgainstLocations(const intrinsic::IntrinsicTriangulation& t0, const intrinsic::IntrinsicTriangulation& t1,
                           const std::vector<Point>& vertexImage, MeshRemeshResult& out, const EdgeInFace& inFace = {});

}  // namespace conformesh::refine::detail
