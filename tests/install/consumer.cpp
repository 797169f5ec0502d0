// consumer.cpp — the README's example of using conformesh from another CMake project: read a mesh, check its
// Gauss–Bonnet residual. Exit 0 when the residual is round-off, 1 otherwise, 2 for bad input (the message names it).
#include <cmath>
#include <iostream>

#include <conformesh/intrinsic/errors.h>
#include <conformesh/intrinsic/io/mesh_io.h>
#include <conformesh/intrinsic/mesh/mesh_summary.h>

int main(int argc, char** argv) {
  using namespace conformesh::intrinsic;
  if (argc != 2) return 2;
  try {
    const IntrinsicTriangulation tri = toTriangulation(readMesh(argv[1]));
    const MeshSummary s = summarize(tri);
    std::cout << "genus " << s.genus << ", Gauss-Bonnet residual " << s.curvature.gaussBonnetResidual << "\n";
    return std::abs(s.curvature.gaussBonnetResidual) < 1e-9 ? 0 : 1;
  } catch (const conformesh::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
