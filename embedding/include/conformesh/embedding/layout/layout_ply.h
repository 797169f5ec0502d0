// layout_ply.h — a layout written as PLY with per-corner domain coordinates, the way texture coordinates are stored
// (face property `list uchar float texcoord`, six numbers u0 v0 u1 v1 u2 v2 per triangle, as MeshLab and Blender read
// them). Per-corner rather than per-vertex because a cut surface has several images of one vertex: a torus or
// hyperbolic surface has one per side of the cut, and only the corners of D are single-valued. docs/layout.md §8.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/layout/disk_layout.h"
#include "conformesh/embedding/layout/fundamental_domain.h"
#include "conformesh/embedding/layout/sphere_layout.h"

namespace conformesh::embedding {

struct CornerLayout {
  std::vector<std::array<int, 3>> faces;                // vertex indices (the uniformized triangulation's faces)
  std::vector<Eigen::Vector3d> positions;               // per vertex; written as x y z (zeros when unknown)
  std::vector<std::array<Eigen::Vector2d, 3>> corners;  // per face: the domain coordinates of its three corners
  std::vector<std::string> comments;                    // header comments (what the coordinates are)
};

// Corner coordinates of each layout: the developed fundamental domain D (tori: the plane; hyperbolic: the Poincaré
// disk), the circle domain, the sphere's stereographic plane (from the north pole).
CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const FundamentalDomain& domain);
CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const DiskLayout& layout);
CornerLayout cornerLayout(const intrinsic::IntrinsicTriangulation& tri, const SphereLayout& layout);

// ASCII PLY. Throws InputError naming the path when it cannot be written or when sizes disagree.
void writeLayoutPly(const CornerLayout& layout, const std::string& path);

}  // namespace conformesh::embedding
