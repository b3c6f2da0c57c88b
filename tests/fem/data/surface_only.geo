// A surface mesh without volume: reading it must fail with "no volume elements".
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Physical Surface("plate") = {1};
Mesh.MeshSizeMax = 0.5;
