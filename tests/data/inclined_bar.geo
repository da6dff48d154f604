// A bar [0, 2] × [0, 1] rotated by 30° about the origin (built-in kernel), for the uniaxial
// patch test with rollers on inclined sides (docs/theory.md §"Loads and supports"). In the
// rotated frame e1 = (cos 30°, sin 30°), e2 = (−sin 30°, cos 30°): End is x' = 0, Base y' = 0,
// Load x' = 2, Top y' = 1.
a = Pi / 6;
c = Cos(a); s = Sin(a);
L = 2;
Point(1) = {0, 0, 0};
Point(2) = {L * c, L * s, 0};
Point(3) = {L * c - s, L * s + c, 0};
Point(4) = {-s, c, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("Base") = {1};
Physical Curve("Load") = {2};
Physical Curve("Top") = {3};
Physical Curve("End") = {4};
Physical Surface("Bar") = {1};
