// A box [0, 2] × [0, 1] × [0, 1] (OpenCASCADE) rotated by 0.5 rad about the axis (1, 2, 3)
// through the origin, for the 3D uniaxial patch test with rollers on three oblique faces
// (docs/theory.md §"Loads and supports"). OpenCASCADE numbers a box's faces x = 0, x = 2, y = 0,
// y = 1, z = 0, z = 1 as surfaces 1 to 6; the names are those of the unrotated box.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Rotate {{1, 2, 3}, {0, 0, 0}, 0.5} { Volume{1}; }
Physical Surface("End") = {1};
Physical Surface("Load") = {2};
Physical Surface("Base") = {3};
Physical Surface("Back") = {4};
Physical Surface("Bottom") = {5};
Physical Surface("Top") = {6};
Physical Volume("Box") = {1};
