// The box (0, 0.03) x (0, 0.01) x (0, 0.01) meshed with tetrahedra, made by extruding the rectangle
// z = 0 along z. Physical groups: "contact" (y = 0), "top" (y = 0.01), "clamped" (x = 0) and the
// volume "body".
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
// extruded[0] is the top (z = 0.01), extruded[1] the volume, extruded[2 + k] the side swept by line k + 1.
extruded[] = Extrude {0, 0, 0.01} { Surface{1}; };
Physical Surface("contact") = {extruded[2]};
Physical Surface("top") = {extruded[4]};
Physical Surface("clamped") = {extruded[5]};
Physical Volume("body") = {extruded[1]};
