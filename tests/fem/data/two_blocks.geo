// Two disconnected blocks: an interface on one cannot hold the other.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.1, 0.02, 0.02};
Box(2) = {0.2, 0, 0, 0.1, 0.02, 0.02};
e = 1e-6;
Physical Volume("blocks") = {1, 2};
Physical Surface("left_end") = Surface In BoundingBox{-e, -e, -e, e, 0.02 + e, 0.02 + e};
Mesh.MeshSizeMax = 0.01;
