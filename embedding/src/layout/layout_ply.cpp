// layout_ply.cpp — per-corner domain coordinates of a layout and their PLY file (texcoord face property). See
// layout_ply.h and docs/layout.md §8.
#include "conformesh/embedding/layout/layout_ply.h"

#include <fstream>
#include <iomanip>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

namespace {

CornerLayout facesOf(const intrinsic::IntrinsicTriangulation& tri) {
  CornerLayout c;
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    c.faces.push_back({tri.mesh.faceVertex(f, 0), tri.mesh.faceVertex(f, 1), tri.mesh.faceVertex(f, 2)});
  c.positions.assign(tri.mesh.nVertices(), Eigen::Vector3d::Zero());
  c.corners.resize(tri.mesh.nFaces());
  return c;
}

}  // namespace

CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const FundamentalDomain& domain) {
  CornerLayout c = facesOf(tri);
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) c.corners[f][k] = {domain.corners[f][k].real(), domain.corners[f][k].imag()};
  c.comments.push_back(domain.background == intrinsic::Background::Euclidean
                           ? "texcoord: fundamental domain of the flat torus in the plane (cut along tree-cotree)"
                           : "texcoord: fundamental domain in the Poincare disk (cut along tree-cotree)");
  return c;
}

CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const DiskLayout& layout) {
  CornerLayout c = facesOf(tri);
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) c.corners[f][k] = layout.points[tri.mesh.faceVertex(f, k)];
  for (int v = 0; v < tri.mesh.nVertices(); ++v) c.positions[v] << layout.points[v], 0;
  c.comments.push_back("texcoord: circle domain (outer boundary the unit circle); x y z the same point, z = 0");
  return c;
}

CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const SphereLayout& layout) {
  CornerLayout c = facesOf(tri);
  for (int f = 0; f < tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) c.corners[f][k] = layout.plane[tri.mesh.faceVertex(f, k)];
  c.positions = layout.points;
  c.comments.push_back("texcoord: stereographic projection from the north pole; x y z the point on the unit sphere");
  return c;
}

void writeLayoutPly(const CornerLayout& layout, const std::string& path) {
  if (layout.corners.size() != layout.faces.size())
    throw InputError(path + ": " + std::to_string(layout.corners.size()) + " corner triples for " +
                     std::to_string(layout.faces.size()) + " faces");
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot open for writing");
  out << "ply\nformat ascii 1.0\ncomment written by conformesh layout\n";
  for (const auto& c : layout.comments) out << "comment " << c << '\n';
  out << "element vertex " << layout.positions.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << layout.faces.size()
      << "\nproperty list uchar int vertex_indices\nproperty list uchar double texcoord\nend_header\n";
  out << std::setprecision(17);
  for (const auto& p : layout.positions) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (std::size_t f = 0; f < layout.faces.size(); ++f) {
    out << "3 " << layout.faces[f][0] << ' ' << layout.faces[f][1] << ' ' << layout.faces[f][2] << " 6";
    for (const auto& c : layout.corners[f]) out << ' ' << c.x() << ' ' << c.y();
    out << '\n';
  }
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace conformesh::embedding
