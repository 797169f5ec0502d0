// teapot_data.h — the Utah teapot: Martin Newell's 1975 bicubic Bézier patches (rim 4, body 8, handle 4, spout 4,
// lid 8) with the 4-patch bottom usually added (after Frank Crow), 32 patches over 306 control points.
//
// Source of the numbers: the classic data set as reproduced in K-3D's modules/aqsis/teapot.cpp (github.com/K-3D/k3d,
// commit 66032dd6f64089a2999021b75cbbf2b1e0cb2d6f), the same 306 points and 1-based patch index lists that circulate
// in many renderers. The paper (Li et al. 2013, Fig. 8, §6.1) meshes "a Bézier patch of the Utah teapot" without
// saying which; `conformesh discretize teapot-patch --param patch=K` selects one.
#pragma once

#include <vector>

#include "conformesh/intrinsic/metric/metric_families.h"

namespace conformesh::intrinsic {

constexpr int kTeapotPatchCount = 32;
constexpr int kTeapotControlPointCount = 306;

// Patch k (0-based) as a control net P[i][j] (i along u, j along v; the data's 16 indices are row-major, rows = v).
BezierControlNet teapotPatch(int k);

// True when one side of patch k collapses to a point (the lid's top 20–23 and the bottom 28–31): such a patch's metric
// degenerates along that side, as at a coordinate pole, and is not offered as a rectangle chart.
bool teapotPatchIsDegenerate(int k);

// The metric of patch k as a SmoothMetric (chart [0,1]², embedding = the patch). Throws InputError for an index out of
// range or a degenerate patch.
std::unique_ptr<ParametricSurfaceMetric> makeTeapotPatch(int k);

}  // namespace conformesh::intrinsic
