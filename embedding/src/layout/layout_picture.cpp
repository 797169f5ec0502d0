// layout_picture.cpp — drawings of canonical-domain layouts (fundamental domain, tiles, generator loops) and their SVG
// text. See layout_picture.h and docs/layout.md §7.
#include "conformesh/embedding/layout/layout_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;

namespace {

Eigen::Vector2d toVec(Complex z) {
  return {z.real(), z.imag()};
}

// The generator loops drawn on the copies of their edges in D: halfedge h at its placement in face(h).
void addGeneratorLoops(const IntrinsicTriangulation& tri, const FundamentalDomain& fd, const Mobius& tile,
                       LayoutDrawing& d) {
  for (int i = 0; i < static_cast<int>(fd.basis.generatorEdges.size()); ++i) {
    for (int h : generatorLoop(tri, fd.basis, i)) {
      DrawnPolyline line;
      line.colour = i + 1;
      line.points = {toVec(applyMobius(tile, fd.corners[h / 3][h % 3])),
                     toVec(applyMobius(tile, fd.corners[h / 3][(h + 1) % 3]))};
      d.lines.push_back(line);
    }
  }
}

void addTiles(const IntrinsicTriangulation& tri, const FundamentalDomain& fd, const std::vector<Mobius>& tiles,
              const PictureOptions& options, LayoutDrawing& d) {
  // tiles[0] is the identity: D itself, always drawn; the others as long as the triangle budget allows.
  const long perTile = tri.mesh.nFaces();
  const std::size_t nTiles =
      std::max<long>(1, std::min<long>(tiles.size(), options.maxTriangles / std::max(1L, perTile)));
  for (std::size_t t = 0; t < nTiles; ++t) {
    for (const auto& c : fd.corners) {
      DrawnTriangle tr;
      tr.layer = t == 0 ? 0 : 1;
      for (int k = 0; k < 3; ++k) tr.corners[k] = toVec(applyMobius(tiles[t], c[k]));
      d.triangles.push_back(tr);
    }
  }
  if (options.drawGenerators) addGeneratorLoops(tri, fd, Mobius::Identity(), d);
}

}  // namespace

LayoutDrawing drawTorus(const IntrinsicTriangulation& tri, const TorusLayout& layout, const PictureOptions& options) {
  LayoutDrawing d;
  char title[96];
  std::snprintf(title, sizeof title, "flat torus, tau = %.6f %+.6fi", layout.tau.real(), layout.tau.imag());
  d.title = title;
  std::vector<Mobius> tiles{Mobius::Identity()};
  const int n = std::max(0, options.tileDepth);
  for (int a = -n; a <= n; ++a)
    for (int b = -n; b <= n; ++b) {
      if (a == 0 && b == 0) continue;
      Mobius m = Mobius::Identity();
      m(0, 1) = double(a) * layout.reducedOmega1 + double(b) * layout.reducedOmega2;
      tiles.push_back(m);
    }
  // Nearest translates first, so that a triangle budget keeps the ring around D.
  std::stable_sort(tiles.begin() + 1, tiles.end(),
                   [](const Mobius& x, const Mobius& y) { return std::abs(x(0, 1)) < std::abs(y(0, 1)); });
  addTiles(tri, layout.domain, tiles, options, d);
  return d;
}

LayoutDrawing drawHyperbolic(const IntrinsicTriangulation& tri, const HyperbolicLayout& layout,
                             const PictureOptions& options) {
  LayoutDrawing d;
  d.title = "hyperbolic surface of genus " + std::to_string(layout.domain.basis.genus) + " in the Poincare disk";
  d.unitCircle = true;
  addTiles(tri, layout.domain, deckWords(layout.domain.generators, std::max(0, options.tileDepth)), options, d);
  return d;
}

LayoutDrawing drawDisk(const IntrinsicTriangulation& tri, const DiskLayout& layout) {
  LayoutDrawing d;
  d.title = layout.circles.size() == 1 ? "unit disk" : "circle domain";
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    DrawnTriangle t;
    for (int k = 0; k < 3; ++k) t.corners[k] = layout.points[tri.mesh.faceVertex(f, k)];
    d.triangles.push_back(t);
  }
  for (const auto& c : layout.circles) {
    DrawnPolyline line;
    line.closed = true;
    for (int k = 0; k < 256; ++k) {
      const double t = 2 * M_PI * k / 256;
      line.points.push_back(c.centre + c.radius * Eigen::Vector2d(std::cos(t), std::sin(t)));
    }
    d.lines.push_back(line);
  }
  return d;
}

LayoutDrawing drawSphere(const IntrinsicTriangulation& tri, const SphereLayout& layout, const Eigen::Vector3d& view) {
  LayoutDrawing d;
  d.title = "unit sphere (balanced)";
  d.unitCircle = true;
  const Eigen::Vector3d w = view.normalized();
  const Eigen::Vector3d u = (std::abs(w.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX()).cross(w);
  const Eigen::Vector3d ex = u.normalized(), ey = w.cross(ex);
  const Eigen::Vector3d light = (w + 0.5 * ey).normalized();
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    const Eigen::Vector3d& a = layout.points[tri.mesh.faceVertex(f, 0)];
    const Eigen::Vector3d& b = layout.points[tri.mesh.faceVertex(f, 1)];
    const Eigen::Vector3d& c = layout.points[tri.mesh.faceVertex(f, 2)];
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    if (n.dot(w) <= 0) continue;  // back-facing
    DrawnTriangle t;
    t.shade = 0.35 + 0.65 * std::max(0.0, n.dot(light));
    int k = 0;
    for (const Eigen::Vector3d* p : {&a, &b, &c}) t.corners[k++] = Eigen::Vector2d(p->dot(ex), p->dot(ey));
    d.triangles.push_back(t);
  }
  return d;
}

std::string toSvg(const LayoutDrawing& drawing, int pixels) {
  if (pixels < 16) throw InputError("toSvg: picture size " + std::to_string(pixels) + " px, expected >= 16");
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  auto grow = [&](const Eigen::Vector2d& p) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  };
  for (const auto& t : drawing.triangles)
    for (const auto& p : t.corners) grow(p);
  for (const auto& l : drawing.lines)
    for (const auto& p : l.points) grow(p);
  if (drawing.unitCircle) grow({-1, -1}), grow({1, 1});
  if (!(x1 > x0) || !(y1 > y0)) x0 = y0 = -1, x1 = y1 = 1;
  const double span = std::max(x1 - x0, y1 - y0), scale = 0.94 * pixels / span;
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  auto px = [&](const Eigen::Vector2d& p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f,%.2f", 0.5 * pixels + scale * (p.x() - cx),
                  0.5 * pixels - scale * (p.y() - cy));
    return std::string(buf);
  };
  // Palette: outline dark grey, then one colour per generator loop (Okabe–Ito, distinguishable for colour-blind eyes).
  static const char* palette[] = {"#333333", "#D55E00", "#0072B2", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << pixels << "\" height=\"" << pixels
    << "\" viewBox=\"0 0 " << pixels << ' ' << pixels << "\">\n"
    << "<title>" << drawing.title << "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const double stroke = std::max(0.15, std::min(1.0, 0.5 * pixels / std::sqrt(1.0 + drawing.triangles.size())));
  if (drawing.unitCircle)
    s << "<circle cx=\"" << 0.5 * pixels + scale * (0 - cx) << "\" cy=\"" << 0.5 * pixels + scale * cy << "\" r=\""
      << scale << "\" fill=\"#f4f4f4\" stroke=\"black\" stroke-width=\"1\"/>\n";
  for (int layer : {1, 0}) {
    s << "<g stroke=\"" << (layer == 0 ? "#1f3b73" : "#9aa7bf") << "\" stroke-width=\"" << stroke
      << "\" stroke-linejoin=\"round\">\n";
    for (const auto& t : drawing.triangles) {
      if (t.layer != layer) continue;
      const int base = layer == 0 ? 200 : 235;
      const int c = static_cast<int>(std::lround(base * t.shade + (255 - base) * (1 - t.shade) * 0.2));
      char fill[16];
      std::snprintf(fill, sizeof fill, "#%02x%02x%02x", std::clamp(c - 20, 0, 255), std::clamp(c, 0, 255), 255);
      s << "<polygon points=\"" << px(t.corners[0]) << ' ' << px(t.corners[1]) << ' ' << px(t.corners[2])
        << "\" fill=\"" << fill << "\"/>\n";
    }
    s << "</g>\n";
  }
  for (const auto& l : drawing.lines) {
    if (l.points.size() < 2) continue;
    s << "<" << (l.closed ? "polygon" : "polyline") << " fill=\"none\" stroke=\"" << palette[l.colour % 7]
      << "\" stroke-width=\"" << (l.colour == 0 ? 2 * stroke : 2.5) << "\" points=\"";
    for (const auto& p : l.points) s << px(p) << ' ';
    s << "\"/>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace conformesh::embedding
