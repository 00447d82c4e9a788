// The paper's strip (0,0.03) x (0,0.01) m as an unstructured triangle mesh, refined toward the contact
// boundary: an example of a scene whose mesh comes from a user's gmsh file. Physical groups become the
// regions the scene names.
lc_contact = 0.0004;
lc_top = 0.0012;
Point(1) = {0, 0, 0, lc_contact};
Point(2) = {0.03, 0, 0, lc_contact};
Point(3) = {0.03, 0.01, 0, lc_top};
Point(4) = {0, 0.01, 0, lc_top};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("body") = {1};
Physical Curve("contact") = {1};
Physical Curve("free_end") = {2};
Physical Curve("top") = {3};
Physical Curve("clamped") = {4};
