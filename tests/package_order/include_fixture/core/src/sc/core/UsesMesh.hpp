#pragma once
// Fixture of package_includes_detects_violation: core may not use mesh.
#include <sc/mesh/SimplexMesh.hpp>
