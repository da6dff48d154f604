// The Hertz half ball (radius 1, centre (0, 0, 1), the lower half, flat side on top) with
// OpenCASCADE, as a user would build it from a CAD sphere. Physical groups "Top" (the flat
// face) and "Cap" (the spherical face). Mesh/Source = "Gmsh geometry" (docs/mesh.md "Curved
// boundaries from files").
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 1, 1};
Box(2) = {-2, -2, 1, 4, 4, 2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
top() = Surface In BoundingBox{-1.1, -1.1, 0.999, 1.1, 1.1, 1.001};
all() = Abs(Boundary{ Volume{3}; });
cap() = all();
cap() -= top();
Physical Surface("Top") = top();
Physical Surface("Cap") = cap();
Physical Volume("Body") = {3};
