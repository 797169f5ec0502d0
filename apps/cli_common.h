// cli_common.h — what every subcommand shares: JSON printing, progress lines on stderr, and turning library errors into
// one-line messages with a non-zero exit status.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::apps {

// Exit statuses: 0 success, 1 bad input or failed computation (message on stderr), 2 bad command line (CLI11),
// 3 an output that failed its verification (refine/pipeline/output_verification.h; kept as NAME.failed.EXT with
// --keep-failed).
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
constexpr int kExitVerification = 3;

// An output that failed its verification; main prints "conformesh: error: <message>" and exits kExitVerification.
struct OutputRejected : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where a command writes its output after `check`: `path` when it passed; refine::failedOutputName(path) when it
// failed and `keepFailed`; "" (write nothing) otherwise. Records report["verification"] (passed, failures, written).
std::string verifiedOutputPath(const refine::OutputVerification& check, bool keepFailed, const std::string& path,
                               nlohmann::json& report);
// After the outputs (if any) are written: when `check` failed, prints the JSON report if `json` and throws
// OutputRejected naming the failures and the kept file (or that `path` was not written).
void rejectIfFailed(const refine::OutputVerification& check, const std::string& path, const std::string& keptPath,
                    bool json, const nlohmann::json& report);
// Each notice as "conformesh: notice: ..." on stderr, also in quiet mode (a result the user did not ask for).
void printNotices(const std::vector<std::string>& notices);
// Registers `--keep-failed` on `sub`.
void addKeepFailedOption(CLI::App* sub, bool& keepFailed);

// Prints `j` to stdout, indented, followed by a newline.
void printJson(const nlohmann::json& j);

// The interpreter for scripts/*.py: CMake's CONFORMESH_PYTHON when it exists (default Debian's /usr/bin/python3),
// else /usr/bin/python3, else "python3" from the PATH.
std::string scriptInterpreter();

// A progress line on stderr ("conformesh: <what>"), unless quiet mode is on (--quiet on the root command).
void progress(const std::string& what);
void setQuiet(bool quiet);
// A (done, total) callback for long loops that prints "conformesh: <what>: done of total (p %)" through progress(), at
// most every 5 seconds (and never for a loop that ends sooner).
std::function<void(int, int)> countingProgress(const std::string& what);

// Reads a mesh file, or throws InputError naming it. With --repair given (addRepairOption), the file is repaired
// (intrinsic/mesh/mesh_repair.h, default RepairOptions) and each repair printed as a progress line; without it, a file
// that only repair would make a manifold is refused with the first defect and a pointer to --repair.
intrinsic::MeshData loadMesh(const std::string& path);
// Registers `--repair` on a command that reads a mesh; loadMesh then repairs what it reads.
void addRepairOption(CLI::App* sub);

// Parses `--param key=value` arguments into a map; throws InputError naming the argument when it is not key=number.
std::map<std::string, double> parseParameters(const std::vector<std::string>& args);

// The --field option of discretize, remesh and convergence: a sampled metric field, text or HDF5 (docs/metrics.md §4).
void addFieldOption(CLI::App* sub, std::string& field);

// The metric a command was given: exactly one of a family name with `--param`s, or a sampled field file. Throws
// InputError, prefixed with `command`, when both or neither are given.
std::unique_ptr<intrinsic::SmoothMetric> loadMetric(const std::string& command, const std::string& family,
                                                    const std::vector<std::string>& params, const std::string& field);

// The curvature check's per-vertex figures as output properties: `error` = φ_T − φ_M of the vertex's region and
// `relative_error`.
void addCurvatureMeasureProperties(intrinsic::MeshData& data, const intrinsic::CurvatureMeasureResult& c);

// Writes `data` to `path` (binary PLY unless `ascii`) and, when `vtkPath` is not empty, the VTK that `makeVtk` builds;
// records both paths in `report` ("output", "vtk").
void writeMeshOutputs(const intrinsic::MeshData& data, const std::string& path, bool ascii, const std::string& vtkPath,
                      const std::function<intrinsic::VtkMesh()>& makeVtk, nlohmann::json& report);

// The end of every remesh: records `check` in `report`, writes the outputs as writeMeshOutputs does when it passed
// (or, with `keepFailed`, under the failed names), then throws OutputRejected (exit 3) if it failed.
void writeVerifiedMeshOutputs(const refine::OutputVerification& check, bool keepFailed, const intrinsic::MeshData& data,
                              const std::string& path, bool ascii, const std::string& vtkPath,
                              const std::function<intrinsic::VtkMesh()>& makeVtk, bool json, nlohmann::json& report);

// Registers `--smoothing N` and `--smoothing-rule odt|centroid` (RefineOptions::smoothingPasses / smoothingRule) on
// `sub`; `note` ends the --smoothing help line (where it applies), "" for none.
void addSmoothingOptions(CLI::App* sub, int& passes, std::string& rule, const std::string& note);

// `v` with an empty description. CLI11 appends a validator's description to the option's type column
// ("INT:INT in [4 - 100000]=48"), which pushes the help text onto a line of its own; the option's text names the
// range or the choices instead, and the help keeps one line per option. The error messages are CLI11's, unchanged.
CLI::Validator untyped(CLI::Validator v);
// untyped(CLI::IsMember(choices)): the option takes one of `choices`.
CLI::Validator oneOf(std::vector<std::string> choices);

}  // namespace conformesh::apps
