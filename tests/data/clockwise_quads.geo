// A 0.03 x 0.01 rectangle whose boundary loop runs clockwise, so that gmsh orients its elements along
// -z, meshed with a structured 6 x 2 grid of quadrilaterals. "contact" is the bottom side.
Point(1) = {0, 0, 0};
Point(2) = {0.03, 0, 0};
Point(3) = {0.03, 0.01, 0};
Point(4) = {0, 0.01, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 7;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("contact") = {1};
Physical Surface("body") = {1};
