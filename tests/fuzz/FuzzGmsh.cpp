// libFuzzer target: a Gmsh .msh file read by sc::mesh::GmshMeshIO::readFile (Gmsh's reader, then
// our extraction: element types, node coordinates, physical groups, SimplexMesh's checks) as for
// Mesh/File. A 2D mesh is read with dimension 2; when the file holds a 3D model the same file is
// read with dimension 3. sc::core::InputError is expected; anything else is a finding. Gmsh
// itself is not instrumented: coverage feedback comes from our code only.
#include <cstddef>
#include <cstdint>
#include <string>

#include <sc/core/Error.hpp>
#include <sc/mesh/GmshMeshIO.hpp>

#include "FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = sc::fuzz::writeInput(data, size, ".msh");
  try {
    sc::mesh::GmshMeshIO::readFile(path, 2);
  } catch (const sc::core::InputError& e) {
    if (std::string(e.what()).find("holds a mesh of dimension 3") != std::string::npos) {
      try {
        sc::mesh::GmshMeshIO::readFile(path, 3);
      } catch (const sc::core::InputError&) {
      }
    }
  }
  return 0;
}
