// main.cpp — the `conformesh` command: a root CLI11 app with one subcommand per pipeline stage. Library errors become
// one line on stderr ("conformesh: error: FILE:LINE: ...") and exit status 1; command-line mistakes exit 2 with hints
// (usage_errors.h); an output that fails its verification (output_verification.h) exits 3.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "usage_errors.h"

int main(int argc, char** argv) {
  CLI::App app{
      "conformesh: intrinsic surface meshing with curvature convergence (Li, Zeng, Morvan, Chen, Gu, TVCG 2013).\n"
      "Metric or triangulation in; Ricci-flow uniformization, graded Delaunay refinement, curvature check out.",
      "conformesh"};
  app.footer("Run `conformesh <command> --help` for each command.\nDetails: docs/cli.md");
  // One line per option: wide enough for the longest "--name TYPE=DEFAULT" column of any subcommand (they share it).
  app.get_formatter()->column_width(33);
  app.require_subcommand(1);
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "Suppress progress lines on stderr");
  app.parse_complete_callback([&] { conformesh::apps::setQuiet(quiet); });

  conformesh::apps::registerInfoCommand(app);
  conformesh::apps::registerDiscretizeCommand(app);
  conformesh::apps::registerGenerateCommand(app);
  conformesh::apps::registerRemeshCommand(app);
  conformesh::apps::registerConvergenceCommand(app);
  conformesh::apps::registerUniformizeCommand(app);
  conformesh::apps::registerRefineCommand(app);
  conformesh::apps::registerLayoutCommand(app);
  conformesh::apps::registerEmbedCommand(app);
  conformesh::apps::registerSweepCommand(app);
  conformesh::apps::registerHorizonsCommand(app);
  conformesh::apps::registerFieldCommand(app);
  conformesh::apps::registerRepairCommand(app);
  conformesh::apps::registerViewCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help (and --help-all) are "errors" with code 0: CLI11 prints the help. Every other kind (CLI11's codes
    // 104–113) is a malformed command line: the documented style and status 2 (usage_errors.h).
    if (e.get_exit_code() == 0) return app.exit(e);
    return conformesh::apps::reportUsageError(app, e.what(), argc, argv);
  } catch (const conformesh::apps::UsageError& e) {
    return conformesh::apps::reportUsageError(app, e.what(), argc, argv);
  } catch (const conformesh::apps::OutputRejected& e) {
    std::cerr << "conformesh: error: " << e.what() << '\n';
    return conformesh::apps::kExitVerification;
  } catch (const conformesh::InputError& e) {
    std::cerr << "conformesh: error: " << e.what() << '\n';
    return conformesh::apps::kExitFailure;
  } catch (const conformesh::ConvergenceError& e) {
    std::cerr << "conformesh: did not converge: " << e.what() << '\n';
    return conformesh::apps::kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "conformesh: internal error: " << e.what() << '\n';
    return conformesh::apps::kExitFailure;
  }
  return 0;
}
