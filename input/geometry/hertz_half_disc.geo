// The Hertz half disc as a user would draw it in Gmsh (built-in kernel): radius 1, centre
// (0, 1), the lower half, the flat side on top. Physical groups name the boundary parts that the
// deck's Boundary Conditions use. Read with Mesh/Source = "Gmsh geometry", Mesh/File = this file:
// StressContact runs the script, meshes it at Mesh/Initial mesh size with quadratic elements on
// the arc, and places every vertex that refinement adds on the arc on the circle
// (docs/mesh.md "Curved boundaries from files").
R = 1;
Point(1) = {0, 1, 0};      // centre of the circle (not meshed)
Point(2) = {-R, 1, 0};
Point(3) = {0, 1 - R, 0};  // lowest point: the first contact point
Point(4) = {R, 1, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("Arc") = {1, 2};
Physical Curve("Top") = {3};
Physical Surface("Body") = {1};
