// layout_picture.h — pictures of a triangulation in its canonical domain (the paper's Figs. 8(c–e), 9(c)): the
// developed fundamental domain with a few tiles of the universal cover (flat tori: translates by the periods;
// hyperbolic surfaces: images under short words in the deck group, inside the Poincaré disk), a circle domain with its
// circles, a sphere layout in orthographic view. A LayoutDrawing is plain data (polygons and polylines in the plane);
// toSvg writes it as SVG, and `conformesh layout` hands the same data to scripts/plot_layout.py (matplotlib) for PNG.
// docs/layout.md §7 says what each picture shows.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/embedding/layout/disk_layout.h"
#include "conformesh/embedding/layout/hyperbolic_layout.h"
#include "conformesh/embedding/layout/sphere_layout.h"
#include "conformesh/embedding/layout/torus_layout.h"

namespace conformesh::embedding {

struct DrawnTriangle {
  std::array<Eigen::Vector2d, 3> corners;
  int layer = 0;       // 0: the fundamental domain (or the whole layout), 1: a tile of the universal cover
  double shade = 1.0;  // fill lightness factor in (0, 1] (sphere: Lambert shading of the face)
};

struct DrawnPolyline {
  std::vector<Eigen::Vector2d> points;
  int colour = 0;  // index into a fixed palette: generator i uses colour i + 1; 0 is the domain's outline
  bool closed = false;
};

struct LayoutDrawing {
  std::string title;
  std::vector<DrawnTriangle> triangles;
  std::vector<DrawnPolyline> lines;
  bool unitCircle = false;  // draw the unit circle (Poincaré disk, disk domains, the sphere's silhouette)
};

struct PictureOptions {
  // Tori: the translates D + mω₁ + nω₂ with |m|, |n| ≤ tileDepth. Hyperbolic: the images of D under every reduced
  // word of length ≤ tileDepth in the 2g generators (1 + 4g + 4g(4g − 1) + … tiles).
  int tileDepth = 1;
  // Tiles are added (in order of word length / distance) only while the picture stays below this many triangles (an
  // SVG triangle is ~60 bytes); D itself is always drawn.
  int maxTriangles = 60000;
  bool drawGenerators = true;  // the 2g generator loops of the tree–cotree basis, one colour each
};

LayoutDrawing drawTorus(const intrinsic::IntrinsicTriangulation& tri, const TorusLayout& layout,
                        const PictureOptions& options = {});
LayoutDrawing drawHyperbolic(const intrinsic::IntrinsicTriangulation& tri, const HyperbolicLayout& layout,
                             const PictureOptions& options = {});
LayoutDrawing drawDisk(const intrinsic::IntrinsicTriangulation& tri, const DiskLayout& layout);
// Orthographic view from the direction `view` (unit vector; faces facing away are not drawn).
LayoutDrawing drawSphere(const intrinsic::IntrinsicTriangulation& tri, const SphereLayout& layout,
                         const Eigen::Vector3d& view = Eigen::Vector3d(0.3, -0.5, 0.81));

// SVG 1.1 text, `pixels` wide and high: y up, the drawing's bounding box fitted with a 3% margin.
std::string toSvg(const LayoutDrawing& drawing, int pixels = 900);

}  // namespace conformesh::embedding
