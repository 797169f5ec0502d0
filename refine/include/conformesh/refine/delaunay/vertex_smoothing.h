// vertex_smoothing.h — one smoothing pass over the free vertices of a refined intrinsic triangulation: each inserted
// interior vertex moves inside its star (vertex_relocation.h) to the point, searched from the star's optimal-Delaunay
// point (or centroid average), that most raises the sum of its triangles' smallest angles, keeping the star's smallest
// angle and the refinement's size and shape bounds. Changes the triangulation's lengths, the moved vertices' input
// locations, λ and signposts; nothing else. Not Delaunay by itself: the refinement re-flips and re-runs its loop after
// each pass (RefineOptions::smoothingPasses). docs/refinement.md §6, *Smoothing*.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/trace/signposts.h"

namespace conformesh::refine {

enum class SmoothingRule {
  // Optimal Delaunay triangulation update (Chen–Xu 2004): the area-weighted mean of the star triangles' circumcentres
  // (centroids for hyperbolic triangles without a circumcircle).
  OptimalDelaunay,
  // The area-weighted mean of the centroids of the star's triangles (the centroidal-Voronoi-like Laplacian rule).
  Centroid,
};
std::string toString(SmoothingRule rule);  // "odt", "centroid"
// Parses "odt" / "centroid"; InputError naming the value otherwise.
SmoothingRule parseSmoothingRule(const std::string& name);

struct SmoothingOptions {
  SmoothingRule rule = SmoothingRule::OptimalDelaunay;
  // The refinement's bounds, kept by every accepted move: circumradius R ≤ ε·e^(−λ̄) (λ̄ the mean of the corners'
  // λ — at the moved vertex from a linear fit over its star —, the refinement queue's estimate of λ at the
  // circumcentre; the exact test is the refinement's, re-run after the pass) and R ≤ B·(shortest edge).
  double epsilon = INFINITY;
  double ratioBound = 1.4142135623730951;

  // What is wrong ("" when valid), expected vs found: ε > 0 (+∞ for no size bound), 1 ≤ B < ∞.
  std::string validate() const;
};

struct SmoothingStatistics {
  std::int64_t candidates = 0;  // free vertices with a star that lays out (inserted, interior, angle sum 2π)
  std::int64_t moved = 0;
  std::int64_t invalid = 0;   // the target and the points ½, ¼ of the way to it all fold the star; not moved
  std::int64_t rejected = 0;  // otherwise not moved: no candidate raised the score within the bounds
};

// One pass, vertices in index order. `inputVertices` = the number of input vertices (never moved); `inputLambda` is λ
// per input vertex (empty: λ ≡ 0, and angles are the background's; otherwise those of e^(2λ)·background); `lambda`
// (per vertex) is re-interpolated at every moved vertex's new location. Candidates: the rule's target, the points ½ and
// ¼ of the way to it, then a compass search from the best of them. Throws InputError with SmoothingOptions::validate's
// text on invalid options.
SmoothingStatistics smoothFreeVertices(intrinsic::IntrinsicTriangulation& tri, Signposts& sp,
                                       std::vector<InputLocation>& locations, std::vector<double>& lambda,
                                       int inputVertices, const InputSurface& input,
                                       const std::vector<double>& inputLambda, const SmoothingOptions& options);

}  // namespace conformesh::refine
