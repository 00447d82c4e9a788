// The paper's strip extruded to a box (0,0.03) x (0,0.01) x (0,0.01) m, tetrahedra, with the physical
// groups the scene box3d.json names as regions.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.03, 0.01, 0.01};
eps = 1e-6;
Physical Volume("body") = {1};
Physical Surface("clamped") = Surface In BoundingBox{-eps, -eps, -eps, eps, 0.01 + eps, 0.01 + eps};
Physical Surface("contact") = Surface In BoundingBox{-eps, -eps, -eps, 0.03 + eps, eps, 0.01 + eps};
Physical Surface("top") = Surface In BoundingBox{-eps, 0.01 - eps, -eps, 0.03 + eps, 0.01 + eps, 0.01 + eps};
Physical Surface("free_end") = Surface In BoundingBox{0.03 - eps, -eps, -eps, 0.03 + eps, 0.01 + eps, 0.01 + eps};
Mesh.CharacteristicLengthMax = 0.002;
