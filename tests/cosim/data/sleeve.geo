// sleeve.geo -- thick cylindrical sleeve for the load/deformation mapping tests.
// Units: metres. Axis z; outer radius 43 mm, inner radius 40 mm, z from -30 to +20 mm.
// Physical groups: sleeve (volume); outer (piston-like: film outside the body),
// inner (bore-like: film inside the body), ends (the two flat annuli: not cylindrical).
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.008, Name "Parameters/size"} ];
r_o = 0.043; r_i = 0.040; z0 = -0.030; z1 = 0.020;
Cylinder(1) = {0, 0, z0, 0, 0, z1 - z0, r_o};
Cylinder(2) = {0, 0, z0 - 0.001, 0, 0, z1 - z0 + 0.002, r_i};
s() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
outer() = {}; inner() = {}; ends() = {};
bnd() = Abs(Boundary{ Volume{s()}; });
For k In {0 : #bnd() - 1}
  bb() = BoundingBox Surface{bnd(k)};
  If (bb(5) - bb(2) < 1e-4)
    ends() += bnd(k);
  ElseIf (bb(3) > 0.5*(r_o + r_i))
    outer() += bnd(k);
  Else
    inner() += bnd(k);
  EndIf
EndFor
Physical Volume("sleeve") = {s()};
Physical Surface("outer") = {outer()};
Physical Surface("inner") = {inner()};
Physical Surface("ends") = {ends()};
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = 0;
Mesh.Algorithm3D = 1;
