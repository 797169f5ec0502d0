// sweep_state.h — a sweep's output folder DIR and what makes it resumable: every file is written to a temporary name
// in its own folder and renamed when complete, a case is finished exactly when DIR/cases/<id>/record.json exists (it
// is written last), and each start of a case appends one line to DIR/cases/<id>/attempts.log. Layout (docs/sweeps.md):
//   DIR/spec.json                     the spec of the last run (as read)
//   DIR/cases/<id>/record.json        the case's record (status, error, inputs, the `remesh --json` keys, producer)
//   DIR/cases/<id>/mesh.ply [.vtk]    the case's output mesh
//   DIR/cases/<id>/attempts.log       one line per start: time, host, pid, rank
//   DIR/table.csv, DIR/table.json     every finished case, in spec order; DIR/orders.json and DIR/groups/ per group
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace conformesh::refine {

// Writes `content` to `path` through "<path's stem>.tmp-<host>-<pid><ext>" in the same folder, flushed, then renamed
// over `path` (atomic on POSIX file systems). Throws InputError naming the path when a step fails.
void writeFileAtomically(const std::string& path, const std::string& content);
// The temporary name writeFileAtomically uses for `path` (for writers that take a path, e.g. the PLY writer).
std::string temporaryNameFor(const std::string& path);
// True for names made by temporaryNameFor (left behind by a killed run).
bool isTemporaryName(const std::string& filename);

struct SweepDir {
  std::string root;
  std::string caseDir(const std::string& id) const;
  std::string recordPath(const std::string& id) const;
  std::string attemptsPath(const std::string& id) const;
};

// The record of a finished case, or nothing when the case has no complete record (not started, or killed).
std::optional<nlohmann::json> readRecord(const SweepDir& dir, const std::string& id);
// Creates DIR/cases/<id> and removes the temporary files a killed attempt left there (called when the case starts:
// only the process that runs a case touches its folder).
void prepareCaseDir(const SweepDir& dir, const std::string& id);
// Appends "START <iso time> host=<h> pid=<p> rank=<r>\n" to the case's attempts.log in one write (O_APPEND).
void logAttempt(const SweepDir& dir, const std::string& id, int rank);

}  // namespace conformesh::refine
