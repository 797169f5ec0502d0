// sphere_layout.h — a genus-0 surface on the unit sphere (intrinsic::uniformize's points of T0*), Möbius-balanced so
// that the weighted centre of mass of its vertices is the origin (which leaves only rotations free), rotated to a
// chosen normalization, and its stereographic projection to the plane. docs/layout.md §5.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"

namespace conformesh::embedding {

struct BalanceOptions {
  // Stop when the weighted centroid is within this distance of the origin: 1e-12 is ~10³ ε of the unit-length points,
  // the level at which the centroid of ~10⁵ points stops being reproducible in double precision.
  double tolerance = 1e-12;
  int maxIterations = 200;
};

// Moves points of the unit sphere by Möbius transformations φ_c(x) = (1 − |c|²)(x − c)/|x − c|² − c (the conformal
// automorphism of the ball moving c to 0, restricted to the sphere) until Σ w_i x_i / Σ w_i is at the origin
// (Springborn's / Kharevych's centring; a unique balanced representative exists up to rotations, Douady–Earle). Each
// step uses c = ¾ × the centroid, since to first order φ_c moves the centroid by −(4/3)c. Returns the iterations
// used; throws ConvergenceError naming the centroid reached when maxIterations do not suffice, InputError when sizes
// differ or a weight is negative.
int balanceOnSphere(std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights,
                    const BalanceOptions& options = {});

struct SphereLayoutOptions {
  // Rotate so that this vertex lies at the south pole (0, 0, −1), the origin of the stereographic plane; −1 keeps the
  // orientation that uniformize produced.
  int centreVertex = -1;
  // Then rotate about the z-axis so that this vertex has longitude 0 (its stereographic image on +x); −1: none.
  int directionVertex = -1;
  BalanceOptions balance;
};

struct SphereLayout {
  std::vector<Eigen::Vector3d> points;  // per vertex, on the unit sphere
  // Stereographic projection from the north pole onto the plane z = 0: (x, y)/(1 − z). Conformal; the south pole goes
  // to 0, the equator to the unit circle, a vertex at the north pole to (+inf, +inf).
  std::vector<Eigen::Vector2d> plane;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // the weighted centroid after balancing
  int balanceIterations = 0;
};

// `weights` per vertex (e.g. a third of the input's incident face areas, which is what uniformize balances); empty:
// uniform weights. Throws InputError when `u` is not a sphere uniformization or a chosen vertex is out of range.
SphereLayout layoutSphere(const intrinsic::Uniformization& u, const std::vector<double>& weights = {},
                          const SphereLayoutOptions& options = {});

// A third of the area of the faces around each vertex (the area measure uniformize balances).
std::vector<double> vertexAreas(const intrinsic::IntrinsicTriangulation& tri);

}  // namespace conformesh::embedding
