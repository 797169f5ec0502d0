// mesh_summary.h — the intrinsic report of a triangulation that `conformesh info` prints: topology (components, χ,
// genus, boundary loops), curvature totals and the Gauss–Bonnet residual, angle, angle-sum and length ranges,
// Delaunay-ness.
#pragma once

#include <vector>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// The figures of one component of a surface of several (its topology is in MeshSummary::components).
struct ComponentFigures {
  double area = 0;
  CurvatureTotals curvature;  // of the component alone: its Gauss–Bonnet residual against 2πχ of the component
};

struct MeshSummary {
  Background background = Background::Euclidean;
  int vertices = 0, edges = 0, faces = 0;
  std::vector<ComponentTopology> components;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;
  // Σ genus over components: for a connected surface, its genus.
  int genus = 0;
  CurvatureTotals curvature;
  double totalArea = 0;
  double minCornerAngle = 0, maxCornerAngle = 0;  // radians
  // The smallest angle sum Σθ at a vertex (radians; interior or boundary) and its vertex: the input's smallest cone
  // angle, which bounds the smallest angle any triangulation keeping that vertex can reach (docs/cli.md).
  double minAngleSum = 0;
  int minAngleSumVertex = -1;
  double minEdgeLength = 0, maxEdgeLength = 0;
  int nonDelaunayEdges = 0;        // interior edges with delaunayMargin < −DelaunayOptions::tolerance
  double nonDelaunayFraction = 0;  // of interior edges
  // Per component, in `components`' order, when there are several (splitComponents); empty for a connected surface.
  std::vector<ComponentFigures> componentFigures;
};

MeshSummary summarize(const IntrinsicTriangulation& tri);

}  // namespace conformesh::intrinsic
