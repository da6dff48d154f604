// An elastic block with rounded top edges, as a user would draw it in Gmsh (the tutorial of
// docs/tutorial.md). Gmsh's built-in kernel: points, lines and circle arcs, a curve loop, a plane
// surface, and physical groups that name the boundary parts the deck's Boundary Conditions use.
W = 2;     // half-width
H = 2;     // height
r = 0.3;   // radius of the rounded top edges
Point(1) = {-W, -H, 0};
Point(2) = { W, -H, 0};
Point(3) = { W, -r, 0};
Point(4) = { W - r, -r, 0};   // centre of the right arc (not meshed)
Point(5) = { W - r, 0, 0};
Point(6) = {-W + r, 0, 0};
Point(7) = {-W + r, -r, 0};   // centre of the left arc (not meshed)
Point(8) = {-W, -r, 0};
Line(1) = {1, 2};             // bottom
Line(2) = {2, 3};             // right side
Circle(3) = {3, 4, 5};        // right rounded edge
Line(4) = {5, 6};             // top
Circle(5) = {6, 7, 8};        // left rounded edge
Line(6) = {8, 1};             // left side
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Curve("Bottom") = {1};
Physical Curve("Sides") = {2, 6};
Physical Curve("Top") = {3, 4, 5};   // the rounded edges too: whatever the indenter may touch
Physical Surface("Block") = {1};
