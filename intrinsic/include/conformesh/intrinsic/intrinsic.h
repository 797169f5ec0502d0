// intrinsic.h — the umbrella header of conformesh::intrinsic: every public header of the library —
// connectivity and length geometry (mesh/), files (io/), smooth metrics (metric/), uniformization by
// discrete Ricci flow (flow/) and the curvature-measure check (measure/). Link conformesh::intrinsic (CMake) or use
// `pkg-config --cflags --libs conformesh`.
//
// Including it costs compile time only; each header alone is self-contained, and tests/install checks that this list
// names every public header of the library. docs/architecture.md says what each file holds.
#pragma once

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/boundary_flattening.h"
#include "conformesh/intrinsic/flow/circle_packing.h"
#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/flow/planar_layout.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/io/vtu_writer.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/measure/horizon_diagnostics.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/from_edge_lengths.h"
#include "conformesh/intrinsic/mesh/halfedge_mesh.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/mesh/mesh_repair.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"
#include "conformesh/intrinsic/metric/field_check.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_families.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/reference_surface.h"
#include "conformesh/intrinsic/metric/sampled_field.h"
#include "conformesh/intrinsic/metric/sampled_field_checks.h"
#include "conformesh/intrinsic/metric/sampled_field_hdf5.h"
#include "conformesh/intrinsic/metric/sampled_spatial_metric.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/intrinsic/metric/spatial_metric.h"
#include "conformesh/intrinsic/metric/teapot_data.h"
