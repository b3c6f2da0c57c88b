// Slab of thickness L = 0.1 m along x (0.02 x 0.02 m cross-section) for 1-D conduction.
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.01, Name "Parameters/size"} ];
L = 0.1; h = 0.02;
Box(1) = {0, 0, 0, L, h, h};
e = 1e-6;
Physical Volume("slab") = {1};
Physical Surface("hot") = Surface In BoundingBox{-e, -e, -e, e, h + e, h + e};
Physical Surface("cold") = Surface In BoundingBox{L - e, -e, -e, L + e, h + e, h + e};
Mesh.MeshSizeMax = size;
