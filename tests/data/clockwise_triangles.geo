// A 0.03 x 0.01 rectangle whose boundary loop runs clockwise, so that gmsh orients its triangles
// along -z. "contact" is the bottom side.
lc = 0.0025;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.03, 0, 0, lc};
Point(3) = {0.03, 0.01, 0, lc};
Point(4) = {0, 0.01, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Surface("body") = {1};
