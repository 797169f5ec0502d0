// embedding_test_meshes.h — meshes of metrics with an embedding, with their vertices in R³ and on the chart's
// reference surface, for the embedding/ tests: the icosahedral T0 of discretizeMetric (positions = position(u, v)),
// and remeshMetric's output T1 (the paper's pipeline).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::testing {

struct PlacedMesh {
  intrinsic::IntrinsicTriangulation tri;
  std::vector<Eigen::Vector3d> positions, reference;
  double meanCircumradius = 0;
};

inline double meanCircumradius(const intrinsic::IntrinsicTriangulation& tri) {
  double sum = 0;
  for (int f = 0; f < tri.mesh.nFaces(); ++f) sum += intrinsic::faceCircumradius(tri, f);
  return sum / tri.mesh.nFaces();
}

// T0 of the metric at `resolution`; edge lengths are the metric's (geodesic) lengths.
inline PlacedMesh discretizedMesh(const intrinsic::SmoothMetric& m, int resolution) {
  intrinsic::DiscretizationOptions o;
  o.resolution = resolution;
  auto data = intrinsic::discretizeMetric(m, o);
  PlacedMesh p;
  intrinsic::ConversionReport report;
  p.tri = intrinsic::toTriangulation(data, &report);
  p.positions.resize(p.tri.mesh.nVertices());
  p.reference.resize(p.tri.mesh.nVertices());
  for (int v = 0; v < data.nVertices; ++v) {
    const int w = report.vertexMap[v];
    if (w < 0) continue;
    const double u = data.vertexProperties.at("u")[v], vv = data.vertexProperties.at("v")[v];
    p.positions[w] = m.position(u, vv);
    p.reference[w] = intrinsic::referencePoint(m.domain(), u, vv);
  }
  p.meanCircumradius = meanCircumradius(p.tri);
  return p;
}

}  // namespace conformesh::testing
