// sweep_spec.h — a sweep specification (docs/sweeps.md): JSON `{"studies": [{"input", "params", "eps" | "vertices",
// "options"}]}` expanded into cases — inputs (family names, sampled fields, mesh files, globs) × parameter grid × option
// grid × resolution levels — each with a stable id computed from what the case means (family or file content,
// parameters, resolution, every remesh option with its default filled in). Reads the spec and hashes input files; no
// other side effects.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace conformesh::refine {

enum class SweepInputKind { Family, Field, Mesh, Horizon };

// One remesh of a sweep.
struct SweepCase {
  int index = 0;       // position in the spec's expansion (studies in order, then inputs, params, options, levels)
  std::string id;      // "<slug>-<16 hex>": FNV-1a 64 of the canonical JSON `key`
  int study = 0;       // index into the spec's "studies"
  std::string group;   // cases that differ only in their level ("eps" or "vertices") share a group: "<slug>-<8 hex>"
  int level = 0;       // index in the study's eps / vertices list
  SweepInputKind kind = SweepInputKind::Family;
  std::string input;   // family name, or the file's path as resolved (relative to the spec's folder)
  std::map<std::string, double> params;  // family parameters (families only)
  double epsilon = 0;                    // > 0, or 0 when targetVertices is given
  int targetVertices = 0;
  // Every remesh option by its long name (ratio, uniform, t0-resolution, disk-target, segment-rule, smoothing,
  // smoothing-rule, refine-in, region, no-check, vtk), defaults filled in (refine-in: "input" for a mesh file,
  // "uniformized" otherwise, as on `remesh`).
  nlohmann::json options;
  nlohmann::json key;  // what the id hashes: input (family or file name + content hash), params, level, options
  double cost = 0;     // relative work estimate (largest first): target vertices, or area-free 1/ε²
  // Horizons only: null = the shape file's own spatial metric (readHorizonMetadata); else {"spatial_metric": NAME,
  // "params": {...}} given by the caller (`conformesh horizons`, horizon_series.h), which puts it in `key`.
  nlohmann::json horizonMetric;

  // The case's inputs as recorded in its record: study, group, input, kind, params, eps / vertices, options.
  nlohmann::json inputsJson() const;
};

struct SweepSpec {
  std::string path;              // the spec file
  nlohmann::json document;       // as read
  std::vector<SweepCase> cases;  // in expansion order; ids are unique (a repeated case is an error)
};

// Reads and expands `path`. Throws InputError "SPEC: studies[i].KEY: what was expected, what was found" for malformed
// JSON, unknown keys, unknown families, files that do not exist, a glob that matches nothing, values of the wrong
// type, or two studies that produce the same case.
SweepSpec readSweepSpec(const std::string& path);
// The same from a parsed document; `path` names it in messages and anchors relative file names.
SweepSpec expandSweepSpec(const nlohmann::json& document, const std::string& path);

// FNV-1a 64-bit of `bytes`, as 16 lower-case hex digits (the case ids' and the file content hashes' function).
std::string fnv1a64Hex(const std::string& bytes);

// The remesh options a spec's "options" may name, with their defaults (long names of `conformesh remesh`); refine-in's
// is that of metrics, a mesh file's case gets "input" (expandSweepSpec), as `remesh` does.
const nlohmann::json& sweepOptionDefaults();

}  // namespace conformesh::refine
