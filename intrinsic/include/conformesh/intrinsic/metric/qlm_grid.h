// qlm_grid.h — the induced 2-metric q_θθ, q_θφ, q_φφ as Einstein Toolkit's QuasiLocalMeasures writes it through
// CarpetIOHDF5, read as a SampledField (sampled_field.h) on the sphere chart u = φ, v = θ.
//
// Layout read (docs/horizons.md "Quasi-local grids" lists the sources and what was assumed):
//   datasets  "QUASILOCALMEASURES::qlm_qtt[S] it=N tl=0 ...", likewise qlm_qtp, qlm_qpp (S = surface index; the
//             thorn's group qlm_twometric[num_surfaces], DIM=2, SIZE=maxntheta,maxnphi), HDF5 shape (MAXNPHI,
//             MAXNTHETA): θ varies fastest (Fortran qlm_qtt(i,j), i = θ); only the first NTHETA × NPHI entries
//             are the surface's.
//   grid      NTHETA, NPHI, NGHOSTSTHETA, NGHOSTSPHI from QuasiLocalMeasures' scalars qlm_ntheta[S], qlm_nphi[S],
//             qlm_nghoststheta[S], qlm_nghostsphi[S] when the file holds them, else from QlmGridOptions.
//   nodes     SphericalSurface without symmetries: Δθ = π/(NTHETA − 2·NGT), θ_i = (i − NGT + ½)Δθ (cell-centred,
//             no node on a pole, ghosts beyond the poles); Δφ = 2π/(NPHI − 2·NGP), φ_j = (j − NGP)Δφ.
// Conversion: ghosts dropped; (u, v) = (φ, θ); g_uu = q_φφ, g_uv = q_θφ, g_vv = q_θθ; `poles both` (the interior θ
// nodes are exactly the sampled field's (j+½)π/NV). Interior NPHI − 2·NGP must be even (a `poles both` requirement).
// Throws InputError naming the file and dataset, and for a bad sample the node: θ and φ index (the file's, ghosts
// included) and position.
#pragma once

#include <string>

#include "conformesh/intrinsic/metric/sampled_field.h"

namespace conformesh::intrinsic {

struct QlmGridOptions {
  int surface = 0;       // S in qlm_qtt[S]
  long iteration = -1;   // it=N of the datasets; -1: the largest present
  // Grid description when the file lacks QuasiLocalMeasures' scalars (0 = take it from the file).
  int ntheta = 0, nphi = 0, nghoststheta = 0, nghostsphi = 0;
  void validate() const;  // throws InputError on negative values or surface < 0
};

// Whether the HDF5 file at `path` holds a dataset named QUASILOCALMEASURES::qlm_qtt[...] (case-insensitive thorn).
bool hasQlmTwoMetric(const std::string& path);

// Reads the 2-metric of one surface at one iteration; see the layout above. Throws InputError.
SampledField readQlmGridHdf5(const std::string& path, const QlmGridOptions& options = {});

}  // namespace conformesh::intrinsic
