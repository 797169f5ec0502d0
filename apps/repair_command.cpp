// repair_command.cpp — `conformesh repair IN -o OUT`: what is almost a surface made into one (intrinsic/mesh/
// mesh_repair.h), each repair reported; the result is checked by toTriangulation (manifold, oriented, valid lengths)
// before it is written. Parsing and printing only.
#include <cstdio>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_repair.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"

namespace conformesh::apps {

namespace {

struct RepairCommandOptions {
  std::string input, output;
  intrinsic::RepairOptions repair;
  bool json = false, ascii = false;
};

nlohmann::json stepJson(const intrinsic::RepairReport::Step& s) {
  return {{"count", s.count}, {"examples", s.examples}};
}

nlohmann::json toJson(const intrinsic::RepairReport& r) {
  return {{"merge_distance", r.mergeDistance},
          {"merged_vertices", stepJson(r.mergedVertices)},
          {"degenerate_faces", stepJson(r.degenerateFaces)},
          {"duplicate_faces", stepJson(r.duplicateFaces)},
          {"non_manifold_edges", stepJson(r.nonManifoldEdges)},
          {"vertex_fans_split", stepJson(r.pinchedVertices)},
          {"reoriented_faces", stepJson(r.reorientedFaces)},
          {"unreferenced_vertices", stepJson(r.unreferencedVertices)}};
}

void runRepair(const RepairCommandOptions& o) {
  const std::string problem = o.repair.validate();
  if (!problem.empty()) throw InputError("repair: " + problem);
  progress("reading " + o.input);
  intrinsic::ReadOptions read;
  read.keepDegenerateFaces = true;
  const intrinsic::MeshData in = intrinsic::readMesh(o.input, read);
  intrinsic::RepairReport report;
  const intrinsic::MeshData out = intrinsic::repairMesh(in, o.repair, &report);
  // The check before writing: a manifold, consistently oriented triangulation with valid lengths.
  intrinsic::ConversionReport conv;
  const intrinsic::IntrinsicTriangulation tri = intrinsic::toTriangulation(out, &conv);
  if (conv.build.reorientedFaces != 0 || conv.unreferencedVerticesRemoved != 0)
    throw std::logic_error("repair left " + std::to_string(conv.build.reorientedFaces) + " faces to reorient and " +
                           std::to_string(conv.unreferencedVerticesRemoved) + " unreferenced vertices");
  const intrinsic::MeshSummary s = intrinsic::summarize(tri);
  nlohmann::json j = toJson(report);
  j["input"] = {{"file", o.input}, {"vertices", in.nVertices}, {"faces", in.faces.size()}};
  j["result"] = {{"vertices", s.vertices},       {"faces", s.faces},
                 {"components", s.components.size()}, {"boundary_loops", s.boundaryLoops},
                 {"euler_characteristic", s.eulerCharacteristic}};
  intrinsic::WriteOptions w;
  if (o.ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(out, o.output, w);
  j["output"] = o.output;
  if (o.json) {
    printJson(j);
    return;
  }
  std::printf("%s: %d vertices, %zu faces -> %d vertices, %d faces, %zu components, %d boundary loops, chi = %d\n",
              o.input.c_str(), in.nVertices, in.faces.size(), s.vertices, s.faces, s.components.size(),
              s.boundaryLoops, s.eulerCharacteristic);
  std::printf("%s", report.changedAnything() ? report.summary().c_str() : "nothing to repair\n");
  std::printf("written to %s\n", o.output.c_str());
}

}  // namespace

void registerRepairCommand(CLI::App& app) {
  auto o = std::make_shared<RepairCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "repair", "Make an almost-surface a manifold mesh: merge, drop degenerate/duplicate faces, cut, orient");
  sub->footer("Example: conformesh repair scan.ply -o scan_fixed.ply\nDetails: docs/cli.md#repair");
  sub->add_option("input", o->input, "Mesh file (.obj, .off, .ply)")->required();
  sub->add_option("-o,--output", o->output, "Repaired mesh (.obj, .off, .ply)")->required();
  sub->add_option("--merge-tolerance", o->repair.mergeTolerance,
                  "Merge vertices closer than this times the bounding-box diagonal (< 0: none)")
      ->capture_default_str();
  sub->add_option("--area-tolerance", o->repair.degenerateTolerance,
                  "Drop faces with area <= this times their longest side squared")
      ->capture_default_str();
  sub->add_flag("--json", o->json, "Print the report as JSON");
  sub->add_flag("--ascii", o->ascii, "Write ASCII PLY (default: binary)");
  sub->callback([o] { runRepair(*o); });
}

}  // namespace conformesh::apps
