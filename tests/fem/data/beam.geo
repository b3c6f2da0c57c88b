// Slender square beam for the Euler–Bernoulli checks: L = 1 m, h = 0.02 m (L/h = 50).
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.01, Name "Parameters/size"} ];
L = 1.0; h = 0.02;
Box(1) = {0, 0, 0, L, h, h};
e = 1e-6;
Physical Volume("beam") = {1};
Physical Surface("clamped") = Surface In BoundingBox{-e, -e, -e, e, h + e, h + e};
Physical Surface("tip") = Surface In BoundingBox{L - e, -e, -e, L + e, h + e, h + e};
Mesh.MeshSizeMax = size;
