// usage_errors.h — command-line mistakes in the documented style (docs/cli.md, first section): one line
// "conformesh: error: COMMAND: MESSAGE" on stderr, then "conformesh: hint: ..." lines for the common mistakes and the
// command's --help and docs section; exit status 2 (kExitUsage). Used by main.cpp for CLI11's parse errors and for
// UsageError, which commands throw for a malformed command line CLI11 cannot see (e.g. neither --eps nor --eps-rel).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace conformesh::apps {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The hints for `message` (CLI11's or a UsageError's) given the command line: convergence with --eps (use
// --vertices/--levels), a misspelt command (the nearest name), -q after the command, a long option with one dash, a
// missing -o or --eps. Empty when none applies. `command` is the subcommand named on the line ("" for none).
std::vector<std::string> usageHints(const CLI::App& app, const std::string& command, const std::string& message,
                                    const std::vector<std::string>& args);

// Prints the error and its hints as above and returns kExitUsage.
int reportUsageError(const CLI::App& app, const std::string& message, int argc, char** argv);

}  // namespace conformesh::apps
