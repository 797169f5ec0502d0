// cli_common.h — what every subcommand shares: JSON printing, progress lines on stderr, and turning library errors into
// one-line messages with a non-zero exit status.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/mesh_data.h"

namespace conformesh::apps {

// Exit statuses: 0 success, 1 bad input or failed computation (message on stderr), 2 bad command line (CLI11).
constexpr int kExitFailure = 1;

// Prints `j` to stdout, indented, followed by a newline.
void printJson(const nlohmann::json& j);

// A progress line on stderr ("conformesh: <what>"), unless quiet mode is on (--quiet on the root command).
void progress(const std::string& what);
void setQuiet(bool quiet);

// Reads a mesh file, or throws InputError naming it.
intrinsic::MeshData loadMesh(const std::string& path);

// Parses `--param key=value` arguments into a map; throws InputError naming the argument when it is not key=number.
std::map<std::string, double> parseParameters(const std::vector<std::string>& args);

}  // namespace conformesh::apps
