// vertex_budget.h — how many vertices a refinement to ε will make, known before it runs, and the refusal of an ε far
// too small for the surface (both remesh pipelines). Reads a uniformized triangulation and λ only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine {

// The default cap on the expected output size. 5·10⁶ vertices is about 2.6 GB and 2–3 minutes at the pipeline's
// measured cost (Kerr a/M = 0.99 at ε = 0.005: 781,191 vertices, 404 MB peak, 20 s on one core), within a
// workstation's memory; an ε that needs more is almost always a mistake in units (a mesh at ×1000 scale, ε meant
// relative: --eps-rel).
constexpr std::int64_t kDefaultMaxVertices = 5'000'000;

// The expected vertex count of refining `uniform` to circumradii ε·e^(−λ): ∫ e^(2λ) dA* / (1.1 ε²) over the uniformized
// surface (e^(2λ) per face from its corners' mean λ; λ empty: uniform), the density Delaunay refinement reaches
// (1.1 ε² of area per vertex, measured in convergence_study.cpp), and never fewer than the input's vertices.
struct VertexEstimate {
  double area = 0;      // ∫ e^(2λ) dA*: the original metric's area as the uniformized surface and λ give it
  double expected = 0;  // vertices
};
VertexEstimate expectedVertices(const intrinsic::IntrinsicTriangulation& uniform, const std::vector<double>& lambda,
                                double epsilon);

// Throws InputError when estimate.expected exceeds maxVertices, naming ε, the expected count, the cap, and the
// smallest ε the cap allows. maxVertices ≤ 0: no cap.
void checkVertexBudget(const VertexEstimate& estimate, double epsilon, std::int64_t maxVertices);

// The refinement's insertion cap for a vertex budget: twice it (the estimate is within a factor 1.5 of the counts
// measured on CGAL's data set and the paper's metrics), so that a refinement running away stops with an error
// naming the cap instead of exhausting memory.
std::int64_t insertionCapFor(std::int64_t maxVertices, std::int64_t current);

// The notice for a refinement that inserted nothing: ε above the largest circumradius of T0 (the output is T0).
std::string epsilonAboveSpacingNotice(double epsilon, double largestCircumradius);

}  // namespace conformesh::refine
