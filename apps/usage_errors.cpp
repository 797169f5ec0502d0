// usage_errors.cpp — command-line mistakes as "conformesh: error: ..." with hints (see usage_errors.h).
#include "usage_errors.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli_common.h"

namespace conformesh::apps {

namespace {

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}
bool has(const std::vector<std::string>& args, const std::string& arg) {
  return std::find(args.begin(), args.end(), arg) != args.end();
}

// Levenshtein distance, for "did you mean" on command names (a dozen short names).
int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::vector<std::string> commandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

// The first argument that names a subcommand ("" when none does).
std::string commandOf(const CLI::App& app, const std::vector<std::string>& args) {
  const std::vector<std::string> names = commandNames(app);
  for (const std::string& a : args)
    if (has(names, a)) return a;
  return "";
}

// No command, or an unknown word where the command goes: the nearest name, else the list.
std::string commandHint(const CLI::App& app, const std::vector<std::string>& args) {
  const std::vector<std::string> names = commandNames(app);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  for (const std::string& a : args) {
    if (a.empty() || a[0] == '-') continue;
    std::string best;
    int bestDistance = 3;  // at most two edits: a typo, not another word
    for (const std::string& n : names)
      if (const int d = editDistance(a, n); d < bestDistance) bestDistance = d, best = n;
    if (!best.empty()) return "did you mean `conformesh " + best + "`?";
    return "the commands are " + list;
  }
  return "give a command: " + list + " (`conformesh --help`)";
}

}  // namespace

std::vector<std::string> usageHints(const CLI::App& app, const std::string& command, const std::string& message,
                                    const std::vector<std::string>& args) {
  std::vector<std::string> hints;
  if (command.empty()) {
    hints.push_back(commandHint(app, args));
    return hints;
  }
  if (command == "convergence" && (has(args, "--eps") || has(args, "--eps-rel")))
    hints.push_back("convergence chooses eps per level from target vertex counts: use --vertices 1k,2k,4k,... or "
                    "--levels N (the paper's Table 2); for one eps use `conformesh remesh`");
  if (has(args, "-q") || has(args, "--quiet"))
    if (contains(message, "not expected")) hints.push_back("-q/--quiet goes before the command: conformesh -q " + command + " ...");
  for (const std::string& a : args)
    if (a.size() > 2 && a[0] == '-' && a[1] != '-' && !std::isdigit(static_cast<unsigned char>(a[1])) && contains(message, a))
      hints.push_back("long options take two dashes: -" + a);
  if (contains(message, "--output is required")) hints.push_back("-o OUT names the output file");
  if (contains(message, "--eps") && contains(message, "required")) hints.push_back("--eps E bounds circumradii in the metric's units; --eps-rel F sets eps = F sqrt(area)");
  return hints;
}

int reportUsageError(const CLI::App& app, const std::string& message, int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::string command = commandOf(app, args);
  // CLI11 says "A subcommand is required" also for a misspelt one: name the word instead.
  std::string what = message;
  if (command.empty())
    for (const std::string& a : args)
      if (!a.empty() && a[0] != '-') {
        what = "unknown command '" + a + "'";
        break;
      }
  std::fprintf(stderr, "conformesh: error: %s%s\n", command.empty() ? "" : (command + ": ").c_str(), what.c_str());
  for (const std::string& h : usageHints(app, command, message, args)) std::fprintf(stderr, "conformesh: hint: %s\n", h.c_str());
  const std::string section = command.empty() ? "" : "#" + command;
  std::fprintf(stderr, "conformesh: hint: `conformesh %s--help`; details: docs/cli.md%s\n",
               command.empty() ? "" : (command + " ").c_str(), section.c_str());
  return kExitUsage;
}

}  // namespace conformesh::apps
