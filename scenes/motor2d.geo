// The stator of a 2D ultrasonic linear motor: a PZT strip (0, 0.03) x (0, 0.003) m, its ends held, four
// electrode segments under it (e1 ... e4, 7.5 mm each) and its top face the grounded electrode that
// touches the slider. A structured mesh: 60 x 6 cells, split into triangles.
nx_segment = 15;
ny = 6;
Point(1) = {0, 0, 0};
Point(2) = {0.0075, 0, 0};
Point(3) = {0.015, 0, 0};
Point(4) = {0.0225, 0, 0};
Point(5) = {0.03, 0, 0};
Point(6) = {0.03, 0.003, 0};
Point(7) = {0, 0.003, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 1};
Transfinite Curve{1, 2, 3, 4} = nx_segment + 1;
Transfinite Curve{6} = 4 * nx_segment + 1;
Transfinite Curve{5, 7} = ny + 1;
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};
Transfinite Surface{1} = {1, 5, 6, 7};
Physical Surface("stator") = {1};
Physical Curve("e1") = {1};
Physical Curve("e2") = {2};
Physical Curve("e3") = {3};
Physical Curve("e4") = {4};
Physical Curve("right") = {5};
Physical Curve("top") = {6};
Physical Curve("left") = {7};
