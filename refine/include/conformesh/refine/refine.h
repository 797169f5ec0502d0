// refine.h — the umbrella header of conformesh::refine: every public header of the library —
// points and geodesics on a triangulation (trace/), intrinsic Delaunay refinement (delaunay/) and the
// remeshing pipelines and studies (pipeline/). Link conformesh::refine.
//
// Including it costs compile time only; each header alone is self-contained, and tests/install checks that this list
// names every public header of the library. docs/architecture.md says what each file holds.
#pragma once

#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/delaunay/vertex_relocation.h"
#include "conformesh/refine/delaunay/vertex_removal.h"
#include "conformesh/refine/delaunay/vertex_smoothing.h"
#include "conformesh/refine/pipeline/component_remesh.h"
#include "conformesh/refine/pipeline/convergence_study.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "conformesh/refine/pipeline/output_verification.h"
#include "conformesh/refine/pipeline/refinement_output.h"
#include "conformesh/refine/pipeline/remesh_json.h"
#include "conformesh/refine/pipeline/horizon_series.h"
#include "conformesh/refine/pipeline/sweep_case.h"
#include "conformesh/refine/pipeline/sweep_run.h"
#include "conformesh/refine/pipeline/sweep_spec.h"
#include "conformesh/refine/pipeline/sweep_state.h"
#include "conformesh/refine/pipeline/sweep_table.h"
#include "conformesh/refine/pipeline/vertex_budget.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/trace/robust_predicates.h"
#include "conformesh/refine/trace/signposts.h"
