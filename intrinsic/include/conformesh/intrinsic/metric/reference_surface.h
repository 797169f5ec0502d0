// reference_surface.h — points and triangles on a chart's pole-free reference surface (smooth_metric.h): unwrapping
// across periodic seams, interpolation inside a triangle, orientation, and the way back to wrapped chart coordinates.
// Used wherever a triangulation's vertices live on a smooth surface (the pull-back, the curvature-measure check).
#pragma once

#include <Eigen/Core>

#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::intrinsic {

// Brings `x` within half a period of `ref` in each periodic direction of a non-polar chart (torus, cylinder), so that
// a triangle straddling a seam is the small triangle it is. Polar charts' reference surfaces have no seams.
Eigen::Vector3d unwrapNear(const ChartDomain& d, const Eigen::Vector3d& ref, Eigen::Vector3d x);

// The chart coordinates of a reference point, wrapped into the chart's periodic ranges.
Eigen::Vector2d chartCoordinates(const ChartDomain& d, const Eigen::Vector3d& x);

// Σ b_k x_k after unwrapping x1, x2 near x0; on the reference sphere the result is projected back to the sphere (the
// gnomonic parametrization of the geodesic triangle, where geodesics are straight).
Eigen::Vector3d interpolateOnReference(const ChartDomain& d, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                                       const Eigen::Vector3d& x2, const Eigen::Vector3d& bary);

// Orientation of a reference triangle: det(x0, x1, x2) on the sphere (positive = counter-clockwise seen from outside),
// the planar cross product of (x1 − x0, x2 − x0) elsewhere (after unwrapping).
double referenceOrientation(const ChartDomain& d, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                            const Eigen::Vector3d& x2);

}  // namespace conformesh::intrinsic
