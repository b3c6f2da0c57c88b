// Bar of length L = 0.1 m along x, 0.02 x 0.02 m cross-section, for 1-D conduction with
// convection at the ends (end0 at x = 0, end1 at x = L) and on the four sides (fin).
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.01, Name "Parameters/size"} ];
L = 0.1; a = 0.02;
Box(1) = {0, 0, 0, L, a, a};
e = 1e-6;
Physical Volume("bar") = {1};
Physical Surface("end0") = Surface In BoundingBox{-e, -e, -e, e, a + e, a + e};
Physical Surface("end1") = Surface In BoundingBox{L - e, -e, -e, L + e, a + e, a + e};
sides() = Surface In BoundingBox{-e, -e, -e, L + e, a + e, a + e};
sides() -= Surface In BoundingBox{-e, -e, -e, e, a + e, a + e};
sides() -= Surface In BoundingBox{L - e, -e, -e, L + e, a + e, a + e};
Physical Surface("sides") = sides();
Mesh.MeshSizeMax = size;
