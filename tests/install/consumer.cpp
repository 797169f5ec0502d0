// consumer.cpp — the README's example of using conformesh from another project, built by run_install_consumer.cmake
// twice against the installed package: with find_package(conformesh) and with `pkg-config --cflags --libs conformesh`.
// It includes only the umbrella header and touches each library once: fromEdgeLengths (intrinsic) on the regular unit
// tetrahedron (closed form: area √3, each vertex's defect π), the mesh file's Gauss–Bonnet residual, vertexAreas
// (embedding) summing to the total area, measureQuality (refine). Exit 0 when every check holds to round-off, 1
// otherwise, 2 for bad input (the message names it).
#include <cmath>
#include <iostream>

#include <conformesh/conformesh.h>

int main(int argc, char** argv) {
  using namespace conformesh::intrinsic;
  if (argc != 2) return 2;
  try {
    const IntrinsicTriangulation tet = fromEdgeLengths({{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}},
                                                       std::vector<std::array<double, 3>>(4, {1.0, 1.0, 1.0}));
    const bool tetOk = std::abs(totalArea(tet) - std::sqrt(3.0)) < 1e-14;  // Heron, a few ulps per face
    const IntrinsicTriangulation tri = toTriangulation(readMesh(argv[1]));
    const MeshSummary s = summarize(tri);
    double areas = 0;
    for (double a : conformesh::embedding::vertexAreas(tri)) areas += a;
    const double residual = conformesh::refine::measureQuality(tri).gaussBonnetResidual;
    std::cout << "tetrahedron area " << totalArea(tet) << "; genus " << s.genus << ", Gauss-Bonnet residual "
              << s.curvature.gaussBonnetResidual << " (refine: " << residual << ")\n";
    const bool areaOk = std::abs(areas - totalArea(tri)) < 1e-12 * totalArea(tri);
    return tetOk && areaOk && std::abs(s.curvature.gaussBonnetResidual) < 1e-9 && std::abs(residual) < 1e-9 ? 0 : 1;
  } catch (const conformesh::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
