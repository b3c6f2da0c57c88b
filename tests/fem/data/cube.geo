// Unit cube, unstructured tetrahedra, for patch tests; all six faces in "boundary".
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.3, Name "Parameters/size"} ];
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("cube") = {1};
Physical Surface("boundary") = {1, 2, 3, 4, 5, 6};
e = 1e-6;
Physical Surface("xmin") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("xmax") = Surface In BoundingBox{1 - e, -e, -e, 1 + e, 1 + e, 1 + e};
Mesh.MeshSizeMax = size;
