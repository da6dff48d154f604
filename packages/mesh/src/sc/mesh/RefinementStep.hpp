#pragma once
// What one call of BisectionRefiner did: enough to transfer fields and contact active sets from the
// previous mesh to the refined one (docs/theory.md §"Adaptivity" "keep the refinement history").

#include <array>
#include <vector>

namespace sc::mesh {

struct RefinementStep {
  int numVerticesBefore = 0;
  int numElementsBefore = 0;
  /// Vertices numVerticesBefore + i (i = 0, 1, ...) are new: the midpoint of the edge between the
  /// two vertices newVertexParents[i], projected onto the curved boundary if the edge lies on one
  /// and boundary projection is on. Parents are older: either old vertices or new ones with a
  /// smaller index (several bisections happen within one call), so a pass in index order can
  /// interpolate.
  std::vector<std::array<int, 2>> newVertexParents;
  /// For every element of the refined mesh: the element of the previous mesh that contains it.
  /// Elements that were not refined keep their index (elementParent[e] == e for them); the first
  /// child of a refined element takes its parent's index, the others are appended.
  std::vector<int> elementParent;
  /// Children of each element of the previous mesh, compressed rows: children[childrenPtr[p] ..
  /// childrenPtr[p+1]) (a single entry p for an element that was not refined).
  std::vector<int> childrenPtr, children;
  /// Number of bisections performed (elements created = numBisections).
  long numBisections = 0;
  /// Wall-clock seconds spent bisecting and rebuilding the mesh connectivity.
  double secondsBisection = 0, secondsMeshBuild = 0;
};

}  // namespace sc::mesh
