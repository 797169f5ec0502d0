// embedding.h — the umbrella header of conformesh::embedding: every public header of the library —
// canonical layouts and pictures (layout/), isometric fits in R³ (fit/) and surfaces in R³
// (extrinsic/). Link conformesh::embedding.
//
// Including it costs compile time only; each header alone is self-contained, and tests/install checks that this list
// names every public header of the library. docs/architecture.md says what each file holds.
#pragma once

#include "conformesh/embedding/extrinsic/embedded_surface.h"
#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"
#include "conformesh/embedding/extrinsic/surface_projection.h"
#include "conformesh/embedding/fit/coarse_to_fine.h"
#include "conformesh/embedding/fit/isometric_embedding.h"
#include "conformesh/embedding/fit/procrustes.h"
#include "conformesh/embedding/layout/disk_layout.h"
#include "conformesh/embedding/layout/fundamental_domain.h"
#include "conformesh/embedding/layout/homology_basis.h"
#include "conformesh/embedding/layout/hyperbolic_layout.h"
#include "conformesh/embedding/layout/layout_picture.h"
#include "conformesh/embedding/layout/layout_ply.h"
#include "conformesh/embedding/layout/sphere_layout.h"
#include "conformesh/embedding/layout/torus_layout.h"
#include "conformesh/embedding/view/view_page.h"
