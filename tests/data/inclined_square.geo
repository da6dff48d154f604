// The unit square [0, 1]² rotated by 30° about the origin (built-in kernel): its sides are
// named as the Unit square scene's (Left: x' = 0, Bottom: y' = 0, Right: x' = 1, Top: y' = 1 in
// the rotated frame e1 = (cos 30°, sin 30°), e2 = (−sin 30°, cos 30°)). Used by the tests of
// conditions in the normal–tangential frame of inclined parts (docs/theory.md §"Loads and
// supports"): Symmetry on Left and Bottom.
a = Pi / 6;
c = Cos(a); s = Sin(a);
Point(1) = {0, 0, 0};
Point(2) = {c, s, 0};
Point(3) = {c - s, s + c, 0};
Point(4) = {-s, c, 0};
Line(1) = {1, 2};  // Bottom
Line(2) = {2, 3};  // Right
Line(3) = {3, 4};  // Top
Line(4) = {4, 1};  // Left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("Bottom") = {1};
Physical Curve("Right") = {2};
Physical Curve("Top") = {3};
Physical Curve("Left") = {4};
Physical Surface("Square") = {1};
