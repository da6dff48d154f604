// The Hertz half disc from a CAD file: input/geometry/half_disc.step (written by OpenCASCADE
// through Gmsh's API: radius 1, centre (0, 1), the lower half, the flat side on top) merged into
// Gmsh's OpenCASCADE kernel. A STEP file has no boundary names: the script names the parts the
// deck's Boundary Conditions use by the curves' tags after the merge (1 and 2 the two quarter
// arcs, 3 the top line; Gmsh's GUI or `gmsh -0 file.geo` lists them). Read with Mesh/Source =
// "Gmsh geometry", Mesh/File = this file; refinement places new vertices on the CAD arcs
// (docs/mesh.md "Curved boundaries from files"). Relative paths in Merge are taken from this
// file's directory.
SetFactory("OpenCASCADE");
Merge "half_disc.step";
Physical Curve("Arc") = {1, 2};
Physical Curve("Top") = {3};
Physical Surface("Body") = {1};
