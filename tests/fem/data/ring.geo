// Thin free ring for the in-plane bending modes: mean radius R = 0.1 m, radial
// thickness t = 0.003 m, axial width w = 0.015 m (t/R = 0.03, w/t = 5 keeps the
// out-of-plane modes above the in-plane n = 2, 3 pairs).
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.0025, Name "Parameters/size"} ];
R = 0.1; t = 0.003; w = 0.015;
Cylinder(1) = {0, 0, 0, 0, 0, w, R + t / 2};
Cylinder(2) = {0, 0, 0, 0, 0, w, R - t / 2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Physical Volume("ring") = {3};
Mesh.MeshSizeMax = size;
