// The inclined bar's shape with its top replaced by a shallow circular arc meshed as one edge
// (Transfinite Curve: two vertices), named Arc: its vertices lie on a line, but the quadratic
// geometry (Mesh/Geometry order = 2) curves the edge along the arc. For the bad input test
// bad_input_loads_symmetry_curved_edge (a Symmetry part must be flat).
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2, 1, 0};
Point(4) = {0, 1, 0};
Point(5) = {1, -3, 0};  // centre of the arc through (2, 1) and (0, 1)
Line(1) = {1, 2};
Line(2) = {2, 3};
Circle(3) = {3, 5, 4};
Line(4) = {4, 1};
Transfinite Curve{3} = 2;
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("Base") = {1};
Physical Curve("Load") = {2};
Physical Curve("Arc") = {3};
Physical Curve("End") = {4};
Physical Surface("Bar") = {1};
