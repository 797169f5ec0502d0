// vertex_budget.cpp — the expected vertex count and the cap (vertex_budget.h).
#include "conformesh/refine/pipeline/vertex_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

VertexEstimate expectedVertices(const IntrinsicTriangulation& uniform, const std::vector<double>& lambda,
                                double epsilon) {
  const HalfedgeMesh& m = uniform.mesh;
  VertexEstimate e;
  for (int f = 0; f < m.nFaces(); ++f) {
    double scale = 1;
    if (!lambda.empty())
      scale = std::exp(2 * (lambda[m.faceVertex(f, 0)] + lambda[m.faceVertex(f, 1)] + lambda[m.faceVertex(f, 2)]) / 3);
    e.area += scale * faceArea(uniform, f);
  }
  e.expected = std::max<double>(m.nVertices(), e.area / (1.1 * epsilon * epsilon));
  return e;
}

void checkVertexBudget(const VertexEstimate& estimate, double epsilon, std::int64_t maxVertices) {
  if (maxVertices <= 0 || estimate.expected <= static_cast<double>(maxVertices)) return;
  std::ostringstream s;
  s.precision(4);
  s << "remesh: eps " << epsilon << " would give about " << estimate.expected << " vertices (area " << estimate.area
    << " / (1.1 eps^2)), above --max-vertices " << maxVertices
    << "; use eps >= " << std::sqrt(estimate.area / (1.1 * static_cast<double>(maxVertices)))
    << " (or --eps-rel, a fraction of sqrt(area)), or raise --max-vertices";
  throw InputError(s.str());
}

std::int64_t insertionCapFor(std::int64_t maxVertices, std::int64_t current) {
  return maxVertices > 0 ? std::min(current, 2 * maxVertices) : current;
}

std::string epsilonAboveSpacingNotice(double epsilon, double largestCircumradius) {
  std::ostringstream s;
  s.precision(6);
  s << "eps " << epsilon << " is above every triangle's size target: no vertex was inserted and the output is the "
    << "input triangulation itself (its largest circumradius is " << largestCircumradius
    << "); use a smaller eps to refine";
  return s.str();
}

}  // namespace conformesh::refine
