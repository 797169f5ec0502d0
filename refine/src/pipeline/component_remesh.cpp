// component_remesh.cpp — remeshMesh component by component and the merged output (component_remesh.h).
#include "conformesh/refine/pipeline/component_remesh.h"

#include <algorithm>
#include <cmath>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::refine {

using intrinsic::describeComponent;

ComponentRemesh remeshComponents(const intrinsic::IntrinsicTriangulation& input,
                                 const std::vector<Eigen::Vector3d>& positions, const MeshRemeshOptions& options) {
  if (const std::string problem = options.validate(); !problem.empty()) throw InputError(problem);
  intrinsic::validateLengths(input, "remesh input");
  ComponentRemesh out;
  // One ε for the whole surface: a relative ε is relative to the whole input, not to each component.
  out.epsilon =
      options.epsilonRelative > 0 ? options.epsilonRelative * std::sqrt(intrinsic::totalArea(input)) : options.epsilon;
  out.components = intrinsic::splitComponents(input);
  const int n = static_cast<int>(out.components.size());
  for (int i = 0; i < n; ++i) {
    const intrinsic::MeshComponent& c = out.components[i];
    MeshRemeshOptions own = options;
    own.epsilon = out.epsilon;
    own.epsilonRelative = 0;
    if (options.progress) {
      const std::string prefix = "component " + std::to_string(i) + "/" + std::to_string(n) + ": ";
      own.progress = [&options, prefix](const std::string& line) { options.progress(prefix + line); };
    }
    std::vector<Eigen::Vector3d> ownPositions;
    if (!positions.empty())
      for (int v : c.vertices) ownPositions.push_back(positions.at(v));
    const std::string where = "remesh: " + describeComponent(i, n, c.topology) + ": ";
    try {
      out.parts.push_back(remeshMesh(c.triangulation, ownPositions, own));
      for (std::string& notice : out.parts.back().notices) notice = describeComponent(i, n, c.topology) + ": " + notice;
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    } catch (const ConvergenceError& e) {
      throw ConvergenceError(where + e.what());
    }
  }
  return out;
}

intrinsic::MeshData mergeComponentOutputs(const ComponentRemesh& result,
                                          const std::vector<intrinsic::MeshData>& parts) {
  if (parts.size() != result.components.size())
    throw InputError("mergeComponentOutputs: " + std::to_string(parts.size()) + " parts for " +
                     std::to_string(result.components.size()) + " components");
  std::vector<intrinsic::MeshData> renumbered = parts;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    auto it = renumbered[i].vertexProperties.find("input_face");
    if (it == renumbered[i].vertexProperties.end()) continue;
    const std::vector<int>& faces = result.components[i].faces;
    for (double& f : it->second) f = faces.at(static_cast<std::size_t>(f));
  }
  intrinsic::MeshData merged = intrinsic::concatenateMeshData(renumbered);
  // Part 0's comments name its own input; the merged file says what it is.
  merged.comments.erase(std::remove_if(merged.comments.begin(), merged.comments.end(),
                                       [](const std::string& c) { return c.rfind("input: ", 0) == 0; }),
                        merged.comments.end());
  int inputVertices = 0, inputFaces = 0;
  for (const auto& c : result.components) {
    inputVertices += c.topology.vertices;
    inputFaces += c.topology.faces;
  }
  merged.comments.push_back("input: " + std::to_string(inputVertices) + " vertices, " + std::to_string(inputFaces) +
                            " faces (input_face, input_b0..2)");
  merged.comments.push_back(std::to_string(parts.size()) +
                            " components, each remeshed alone (vertex property component)");
  return merged;
}

OutputVerification verifyComponentRemesh(const ComponentRemesh& result, const VerificationTolerances& tolerances) {
  OutputVerification out;
  const int n = static_cast<int>(result.parts.size());
  for (int i = 0; i < n; ++i) {
    const OutputVerification one = verifyMeshRemesh(result.parts[i], result.components[i].triangulation, tolerances);
    for (const std::string& f : one.failures)
      out.failures.push_back(describeComponent(i, n, result.components[i].topology) + ": " + f);
    out.facesChecked += one.facesChecked;
    if (std::abs(one.areaRelativeError) > std::abs(out.areaRelativeError))
      out.areaRelativeError = one.areaRelativeError;
  }
  return out;
}
}  // namespace conformesh::refine
