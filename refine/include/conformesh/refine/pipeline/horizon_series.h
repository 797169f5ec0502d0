// horizon_series.h — a time series of horizons (`conformesh horizons SERIES -o DIR`, docs/horizons.md §5c): a folder
// of Strahlkörper shape files, each step run as one case of the sweep engine (sweep_run.h: its own child process,
// record DIR/cases/<id>/record.json, resumable, a failing step recorded and the others run), gathered into one table
// ordered by time, DIR/series.csv and DIR/series.json. Also the Kerr–Schild test series a user can try it on.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/refine/pipeline/sweep_spec.h"

namespace conformesh::refine {

struct HorizonSeriesOptions {
  std::string series;         // a folder of *.json shape files, or an HDF5 file with one shape group per step
  std::string spatialMetric;  // "" = each file's own "spatial_metric" (default kerr-schild); else for every step
  std::map<std::string, double> params;  // --param: over the file's "params"
  double epsilon = 0.2;                  // remesh ε of every step
  bool check = true;                     // the Gaussian curvature measure check (e_G); false = no e_G column

  // What is wrong with these options ("" when valid).
  std::string validate() const;
};

// One step of the series: its file and its time — the file's "time" key, else the last number in the file's name
// (t0012.5.json → 12.5), else none (the step is run and its row has time null).
struct HorizonStep {
  std::string file;
  bool hasTime = false;
  double time = 0;
  std::string timeSource;  // "file" | "name" | "none"
};

// The steps of options.series, ordered by time (steps without a time last, then by name): the .json files of a
// folder, or the shape groups of one HDF5 file (listHorizonShapeGroups; step file "FILE.h5:/group", its time the
// group's attribute `time`, else the last number in the group's name). Throws InputError when the folder does not
// exist or holds no .json file, or the HDF5 file no shape group.
std::vector<HorizonStep> listHorizonSteps(const std::string& folder);

// How a step is named in the table and in errors: the JSON file's name, or "FILE.h5:/group".
std::string horizonStepLabel(const std::string& file);

// The sweep specification of the series: one study per step, named by its file's stem (so that
// a step added later leaves the other steps' ids unchanged), with the steps' spatial metric and
// parameters (options above, merged with each file's metadata) and ε; SweepCase::horizonMetric set on every case.
SweepSpec horizonSeriesSpec(const std::vector<HorizonStep>& steps, const HorizonSeriesOptions& options);

// The table: one row per step, in series order, from the records in `dir` — step, file, time, time_source, status,
// error_kind, vertices, area (smooth metric), mesh_area, irreducible_mass, equatorial_circumference,
// polar_circumference, spin, total_curvature (∫K dA of the mesh, its angle deficits), smooth_total_curvature (∫K dA of
// the smooth metric by quadrature), gauss_bonnet_residual, e_G (mean |error| of the curvature measure, null without
// the check), min_angle_deg, wall_seconds, id, error (free text last, the file named as listed). A step without a
// record has status "missing".
nlohmann::json horizonSeriesRows(const std::vector<HorizonStep>& steps, const SweepSpec& spec, const std::string& dir);

// Writes DIR/series.json ({"rows": rows, "run": run}) and DIR/series.csv (the same rows, columns in the order above),
// atomically, then reads both back and checks them against `rows` (InputError naming the file otherwise). Returns
// the paths written.
std::vector<std::string> writeHorizonSeriesTable(const nlohmann::json& rows, const nlohmann::json& run,
                                                 const std::string& dir);

// The Kerr–Schild test series: n shape files DIR/t<time>.json, times t_k = k·dt, spin a_k = a0 + (a1 − a0) k/(n − 1),
// mass M; each the horizon r = r₊ of Kerr–Schild coordinates, the spheroid (x² + y²)/(r₊² + a²) + z²/r₊² = 1,
// fitted at lMax (fitStrahlkorper), with keys "spatial_metric": "kerr-schild", "params": {"M", "a"}, "time". Returns
// the files written. Throws InputError for n < 1, |a| ≥ M or lMax < 0.
std::vector<std::string> writeKerrHorizonSeries(const std::string& dir, int n, double a0, double a1, double mass,
                                                double dt, int lMax);

// The same series in one HDF5 file, one group per step, "/t<time>" (strahlkorper_io.h's layout, attributes time,
// spatial_metric, param_M, param_a): the fitted coefficients, or with `sampled` the spheroid's radius itself on a
// 2(lMax + 1) × 4(lMax + 1) Gauss–Legendre × uniform θ–φ grid with attribute l_max = lMax (fitted on reading by the exact quadrature).
// Returns "FILE.h5:/group" of each step.
std::vector<std::string> writeKerrHorizonSeriesHdf5(const std::string& path, int n, double a0, double a1, double mass,
                                                    double dt, int lMax, bool sampled);

}  // namespace conformesh::refine
