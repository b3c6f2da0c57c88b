// Quarter of a thick-walled cylinder for the Lamé check: inner radius a = 0.05 m,
// outer b = 0.1 m, height 0.02 m; symmetry planes x = 0, y = 0, z = 0.
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.01, Name "Parameters/size"} ];
a = 0.05; b = 0.1; H = 0.02;
Cylinder(1) = {0, 0, 0, 0, 0, H, b, Pi / 2};
Cylinder(2) = {0, 0, 0, 0, 0, H, a, Pi / 2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6;
Physical Volume("cylinder") = {3};
Physical Surface("sym_x") = Surface In BoundingBox{-e, -e, -e, e, b + e, H + e};
Physical Surface("sym_y") = Surface In BoundingBox{-e, -e, -e, b + e, e, H + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
inner() = Surface In BoundingBox{-e, -e, -e, a + e, a + e, H + e};
inner() -= Surface In BoundingBox{-e, -e, -e, e, b + e, H + e};
inner() -= Surface In BoundingBox{-e, -e, -e, b + e, e, H + e};
inner() -= Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
inner() -= Surface In BoundingBox{-e, -e, H - e, b + e, b + e, H + e};
Physical Surface("inner") = inner();
Mesh.MeshSizeMax = size;
