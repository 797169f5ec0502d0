// commands.h — the conformesh subcommands. Each lives in its own <name>_command.cpp, registers itself on the root
// CLI11 app, parses and prints, and leaves every computation to the libraries.
#pragma once

#include <CLI/CLI.hpp>

namespace conformesh::apps {

void registerInfoCommand(CLI::App& app);
void registerDiscretizeCommand(CLI::App& app);
void registerGenerateCommand(CLI::App& app);
void registerRemeshCommand(CLI::App& app);
void registerConvergenceCommand(CLI::App& app);
void registerUniformizeCommand(CLI::App& app);
void registerRefineCommand(CLI::App& app);
void registerLayoutCommand(CLI::App& app);
void registerEmbedCommand(CLI::App& app);
void registerSweepCommand(CLI::App& app);
void registerHorizonsCommand(CLI::App& app);
void registerFieldCommand(CLI::App& app);
void registerRepairCommand(CLI::App& app);
void registerViewCommand(CLI::App& app);

}  // namespace conformesh::apps
