// sweep_table.h — the table of a sweep: every finished case's record gathered from DIR in spec order, as
// DIR/table.json (a list of records) and DIR/table.csv (one row per case, the main figures), and per group (cases
// that differ only in their level) the fitted convergence orders (DIR/orders.json) and a study file in the format
// of `conformesh convergence`'s JSON (DIR/groups/<group>.json) that scripts/plot_convergence.py draws.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/refine/pipeline/sweep_spec.h"

namespace conformesh::refine {

struct SweepTable {
  int total = 0;                        // cases in the spec
  int ok = 0, failed = 0, timeout = 0;  // records by status
  int missing = 0;                      // cases without a record (not run yet, or run by another job)
  nlohmann::json records = nlohmann::json::array();  // in spec order
  nlohmann::json orders = nlohmann::json::array();   // per group
  std::vector<std::string> groupFiles;  // DIR/groups/<group>.json of the groups with >= 2 ok levels
  std::vector<std::string> written;     // every file written
};

// Reads the records of `spec`'s cases from `dir` and writes the table, the orders and the group files (atomically).
SweepTable writeSweepTable(const SweepSpec& spec, const std::string& dir);

// Fitted orders of one group's ok records (least-squares log-log slopes, intrinsic/measure/convergence_order.h):
// e_G against mean circumradius, mean circumradius against vertices, |area error| against mean circumradius (metrics,
// against the smooth area); null where fewer than two positive points.
nlohmann::json groupOrders(const std::vector<nlohmann::json>& okRecords);

// The record minus its wall-clock fields ("seconds", "wall_seconds" at any depth): what two runs of a case share.
nlohmann::json withoutTimes(const nlohmann::json& record);

}  // namespace conformesh::refine
