// disk_layout.h — a genus-0 surface with boundary laid out in the plane in its circle domain (intrinsic::uniformize:
// the outer loop the unit circle, every other loop a circle), Möbius-normalized: the automorphism
// z ↦ e^{iφ}(z − a)/(1 − āz) of the unit disk puts a chosen vertex at 0 and a second one on the positive x-axis.
// Such a map keeps circles circles, so the result is again a circle domain. docs/layout.md §6.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::embedding {

struct DiskLayoutOptions {
  int centreVertex = -1;     // goes to 0 (must be interior); −1 keeps uniformize's centring
  int directionVertex = -1;  // then rotated onto the positive x-axis; −1: no rotation
};

struct DiskLayout {
  std::vector<Eigen::Vector2d> points;  // per vertex
  // Per boundary loop (HalfedgeMesh::boundaryLoops order): the least-squares circle's centre and radius and the max
  // relative deviation | |p − c| − ρ | / ρ of the loop's vertices.
  struct Circle {
    Eigen::Vector2d centre;
    double radius = 0, deviation = 0;
  };
  std::vector<Circle> circles;
  double minSignedArea = 0;  // min over faces of the layout triangle's signed area (> 0: every face positive)
};

// Throws InputError when `u` is not a circle-domain uniformization or a chosen vertex is out of range (or the centre
// is a boundary vertex).
DiskLayout layoutDisk(const intrinsic::Uniformization& u, const DiskLayoutOptions& options = {});

}  // namespace conformesh::embedding
