// A 0.03 x 0.01 rectangle meshed with triangles. Physical groups: "contact" (bottom side),
// "top" (top side), "clamped" (left side) and the surface "body".
lc = 0.0025;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.03, 0, 0, lc};
Point(3) = {0.03, 0.01, 0, lc};
Point(4) = {0, 0.01, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("contact") = {1};
Physical Curve("top") = {3};
Physical Curve("clamped") = {4};
Physical Surface("body") = {1};
