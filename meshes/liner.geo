// liner.geo -- parametric wet cylinder liner of the flexehd example engine
// (bore 86 mm).
//
// Units: metres.  Frame: z = cylinder axis, positive towards the cylinder head,
// origin on the axis in the plane of the liner top face (head deck); the liner
// extends to z < 0.  +x = major thrust side, y = pin axis direction.  Dimensions,
// their sources, the physical groups and measured mesh statistics are documented
// in docs/meshes.md.
//
// Physical groups: liner (volume); bore, outer, top_seat, bottom_seat, top_face,
//   bottom_face (surfaces: every boundary face belongs to exactly one of these),
//   plus coolant (the wet-zone cylinder, a subset of outer).
//
// Parameter "size" = target element edge length [m]; documented sizes:
//   coarse 0.009, default 0.005, production 0.0035.
// Mesh by hand:  gmsh liner.geo -3 -order 2 -setnumber size 0.005 -o liner.msh
// A program overrides the size through onelab ("Parameters/size") before opening
// the file.  The element order is left to the loader on purpose.

SetFactory("OpenCASCADE");

DefineConstant[ size = {0.005, Name "Parameters/size"} ];

mm = 1e-3;

// ---- dimensions -----------------------------------------------------------------
D      = 86.0*mm;          // bore
R_i    = D/2;              // bore radius
L      = 160.0*mm;         // overall length (top face z = 0, bottom face z = -L)
R_f    = 53.0*mm;          // flange outer radius (flange OD 106 mm)
h_f    = 8.0*mm;           // flange height; its underside (z = -h_f) is the top seat
R_u    = 50.5*mm;          // upper locating band radius (OD 101 mm)
z_u    = -18.0*mm;         // bottom of the upper locating band
R_w    = 49.5*mm;          // wet (coolant) zone radius: wall 6.5 mm
h_t    = 3.0*mm;           // axial length of the conical transitions
z_l    = -145.0*mm;        // top of the lower sealing band
R_l    = 50.5*mm;          // lower sealing band radius (OD 101 mm)

// ---- solid of revolution: profile in the (y, z) half-plane revolved about z -------
p[] = {};
p[] += newp; Point(p[#p[]-1]) = {0, R_i, 0};
p[] += newp; Point(p[#p[]-1]) = {0, R_f, 0};
p[] += newp; Point(p[#p[]-1]) = {0, R_f, -h_f};
p[] += newp; Point(p[#p[]-1]) = {0, R_u, -h_f};
p[] += newp; Point(p[#p[]-1]) = {0, R_u, z_u};
p[] += newp; Point(p[#p[]-1]) = {0, R_w, z_u - h_t};
p[] += newp; Point(p[#p[]-1]) = {0, R_w, z_l + h_t};
p[] += newp; Point(p[#p[]-1]) = {0, R_l, z_l};
p[] += newp; Point(p[#p[]-1]) = {0, R_l, -L};
p[] += newp; Point(p[#p[]-1]) = {0, R_i, -L};
c[] = {};
For i In {0 : #p[] - 1}
  c[] += newl; Line(c[i]) = {p[i], p[(i + 1) % #p[]]};
EndFor
cl = newll; Curve Loop(cl) = {c[]};
prof = news; Plane Surface(prof) = {cl};
rev[] = Extrude {{0,0,1}, {0,0,0}, 2*Pi} { Surface{prof}; };
Recursive Delete { Surface{prof}; }   // the profile is not part of the closed solid
liner = rev[1];

// ---- physical groups: classify every boundary face by its bounding box ----------
tol = 5e-5;   // > OpenCASCADE bounding-box enlargement (~5 um), << feature sizes
bore() = {}; topf() = {}; tseat() = {}; outer() = {}; wet() = {}; bseat() = {}; botf() = {};
bnd() = Abs(Boundary{ Volume{liner}; });
For i In {0 : #bnd() - 1}
  s = bnd(i);
  bb() = BoundingBox Surface{s};
  x0 = bb(0); z0 = bb(2); x1 = bb(3); z1 = bb(5);
  flat = (z1 - z0 < tol);
  If (!flat && x1 < R_i + tol)
    bore() += s;
  ElseIf (flat && Fabs(z1) < tol)
    topf() += s;
  ElseIf (flat && Fabs(z1 + h_f) < tol)
    tseat() += s;
  ElseIf (flat && Fabs(z1 + L) < tol)
    botf() += s;
  ElseIf (z1 < z_l + tol)
    bseat() += s;
  Else
    outer() += s;
    If (x1 < R_w + tol)
      wet() += s;
    EndIf
  EndIf
EndFor

Physical Volume("liner") = {liner};
Physical Surface("bore") = {bore()};
Physical Surface("outer") = {outer()};
Physical Surface("top_seat") = {tseat()};
Physical Surface("bottom_seat") = {bseat()};
Physical Surface("top_face") = {topf()};
Physical Surface("bottom_face") = {botf()};
Physical Surface("coolant") = {wet()};

// ---- mesh size --------------------------------------------------------------------
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = 0;
Mesh.Algorithm3D = 1;           // Delaunay: deterministic (HXT in Gmsh 4.8 is not)
Mesh.OptimizeThreshold = 0.6;   // optimise every tetrahedron of quality < 0.6 (default 0.3)
Mesh.HighOrderOptimize = 1;     // acts only if a curved element has a poor Jacobian ratio
