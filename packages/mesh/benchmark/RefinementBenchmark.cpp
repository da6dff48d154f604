// Refinement throughput (docs/mesh.md): uniform bisection of the half disc (2D) and the half ball
// (3D) up to about --max-elements elements (default 10^6), printing for each level the elements
// created per second by the bisection itself and including the rebuild of the mesh connectivity;
// then a local-refinement run (elements around one boundary point).
//   mesh_refinement_benchmark [--max-elements=N] [--dim=2|3|0]   (0 = both)
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace sc::mesh;

namespace {

void run(const Teuchos::RCP<const Geometry>& g, double h0, long maxElements)
{
  const int factor = g->dim() == 2 ? 4 : 8;
  BisectionRefiner r(GmshMeshIO::meshGeometry(*g, h0), g, true);
  std::printf("%s (initial h = %g): %d elements, min angle %.3f deg\n", g->sceneName().c_str(), h0,
              r.mesh()->numElements(), r.mesh()->minAngleDeg());
  std::printf("  %10s %10s %12s %12s %14s %14s\n", "elements", "vertices", "bisect [s]",
              "rebuild [s]", "created/s", "incl. rebuild");
  // Stop at the first level reaching maxElements, or before one that would exceed 2 x maxElements.
  while (r.mesh()->numElements() < maxElements &&
         static_cast<long>(r.mesh()->numElements()) * factor <= 2 * maxElements) {
    const auto& s = r.refineUniformly();
    const double created = static_cast<double>(r.mesh()->numElements() - s.numElementsBefore);
    std::printf("  %10d %10d %12.3f %12.3f %14.3e %14.3e\n", r.mesh()->numElements(),
                r.mesh()->numVertices(), s.secondsBisection, s.secondsMeshBuild,
                created / s.secondsBisection, created / (s.secondsBisection + s.secondsMeshBuild));
  }
  std::printf("  min angle after uniform refinement: %.3f deg\n", r.mesh()->minAngleDeg());
  // Local refinement on the finest mesh: the elements around vertex 0 (a corner of the domain).
  auto [b, e] = r.mesh()->vertexElements(0);
  const std::vector<int> marked(b, e);
  const int before = r.mesh()->numElements();
  const auto& s = r.refine(marked);
  std::printf("  local: %zu marked -> %d elements created, bisect %.4f s, rebuild %.3f s\n",
              marked.size(), r.mesh()->numElements() - before, s.secondsBisection,
              s.secondsMeshBuild);
}

}  // namespace

int main(int argc, char** argv)
{
  long maxElements = 1000000;
  int dim = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strncmp(argv[i], "--max-elements=", 15))
      maxElements = std::stol(argv[i] + 15);
    else if (!std::strncmp(argv[i], "--dim=", 6))
      dim = std::stoi(argv[i] + 6);
    else {
      std::fprintf(stderr, "usage: %s [--max-elements=N] [--dim=2|3|0]\n", argv[0]);
      return 2;
    }
  }
  if (dim != 3) run(Teuchos::rcp(new HalfDiscGeometry(1.0)), 0.1, maxElements);
  if (dim != 2) run(Teuchos::rcp(new HalfBallGeometry(1.0)), 0.19, maxElements);
  return 0;
}
