// triangle_geometry.h — one geodesic triangle known by its three side lengths, in a background of constant curvature
// 0 (Euclidean), +1 (spherical, unit sphere) or −1 (hyperbolic plane).
//
// Pure functions, no mesh. Every formula is written in a form that keeps full relative accuracy for needles (one side
// tiny) and caps (one angle near π), where the naive law of cosines loses all digits: angles by the half-angle tangent
// with Kahan's ordering of the differences s−a, areas by Kahan's Heron / l'Huilier / its hyperbolic analogue, third
// sides by the haversine forms. docs/theory.md derives them.
#pragma once

#include <string>

namespace conformesh::intrinsic {

enum class Background { Euclidean, Spherical, Hyperbolic };

// Gaussian curvature of the background: 0, +1, −1.
inline double backgroundCurvature(Background g) {
  return g == Background::Euclidean ? 0.0 : (g == Background::Spherical ? 1.0 : -1.0);
}
std::string toString(Background g);  // "euclidean", "spherical", "hyperbolic"
// Parses the names above; throws InputError naming `source` otherwise.
Background backgroundFromString(const std::string& name, const std::string& source = "");

// The three half-perimeter differences s−a, s−b, s−c and s, computed with Kahan's parenthesization so that a cap
// (a ≈ b + c) keeps the relative accuracy of its inputs.
struct HalfPerimeter {
  double s, sa, sb, sc;
};
// Inline: every corner angle, area and validity test goes through here (in refinement, 5 % of all instructions as an
// out-of-line call with an index sort). With sides sorted x ≥ y ≥ z: s − x = (z − (x − y))/2, s − y = (z + (x − y))/2,
// s − z = (x + (y − z))/2, s = (x + (y + z))/2 — the same expressions as before, so the same doubles (equal sides give
// equal differences whichever order the sort leaves them in).
inline HalfPerimeter halfPerimeter(double a, double b, double c) {
  double sa, sb, sc, x, y, z;
  // The difference of the largest side, the middle one and the smallest, for x ≥ y ≥ z (Kahan's parenthesization).
  auto diffs = [](double x_, double y_, double z_, double& dx, double& dy, double& dz) {
    dx = 0.5 * (z_ - (x_ - y_));
    dy = 0.5 * (z_ + (x_ - y_));
    dz = 0.5 * (x_ + (y_ - z_));
  };
  if (!(a < b)) {    // a ≥ b
    if (!(b < c)) {  // a ≥ b ≥ c
      x = a, y = b, z = c;
      diffs(x, y, z, sa, sb, sc);
    } else if (!(a < c)) {  // a ≥ c > b
      x = a, y = c, z = b;
      diffs(x, y, z, sa, sc, sb);
    } else {  // c > a ≥ b
      x = c, y = a, z = b;
      diffs(x, y, z, sc, sa, sb);
    }
  } else {           // b > a
    if (!(a < c)) {  // b > a ≥ c
      x = b, y = a, z = c;
      diffs(x, y, z, sb, sa, sc);
    } else if (!(b < c)) {  // b ≥ c > a
      x = b, y = c, z = a;
      diffs(x, y, z, sb, sc, sa);
    } else {  // c > b > a
      x = c, y = b, z = a;
      diffs(x, y, z, sc, sb, sa);
    }
  }
  return {0.5 * (x + (y + z)), sa, sb, sc};
}

// True when a, b, c are finite, positive and satisfy the strict triangle inequality; on the sphere also a+b+c < 2π
// (the triangle fits in a hemisphere's complement, i.e. is a proper convex spherical triangle).
bool isValidTriangle(Background g, double a, double b, double c);

// Interior angle opposite side a. Requires isValidTriangle.
double angleOpposite(Background g, double a, double b, double c);

// Area (for the sphere and hyperbolic plane: the angle excess/defect, by l'Huilier's formula and its analogue).
double triangleArea(Background g, double a, double b, double c);

// Geodesic circumradius. In the hyperbolic plane a triangle whose three vertices lie on a horocycle or hypercycle has
// no circumcircle: +infinity is returned. Spherical circumradii of valid triangles are below π/2.
double circumradius(Background g, double a, double b, double c);

// Length of the third side opposite an angle `theta` enclosed by sides b and c (the law of cosines in haversine form,
// accurate for small theta and for b ≈ c).
double thirdSide(Background g, double b, double c, double theta);

// cot of the angle opposite a (Euclidean cotangent weights are ½(cot α + cot β)).
double cotOpposite(Background g, double a, double b, double c);

}  // namespace conformesh::intrinsic
