// liner_block.geo -- the wet liner of meshes/liner.geo bonded into a single-cylinder
// section of a cast-iron engine block, meshed as one conformal body (liner and block share
// the nodes of their contact faces), for slap-noise (vibration and radiation) studies.
//
// Units: metres.  Frame: that of liner.geo: z = cylinder axis, positive towards the
// cylinder head, origin on the axis in the deck plane (the liner top face is flush with
// the deck); +x = major thrust side, y = pin axis direction.  Dimensions, their sources,
// the physical groups and measured mesh statistics are documented in docs/meshes.md.
//
// Physical groups: liner, block (volumes); bore, top_face, bottom_face, deck, block_outer,
//   base, jacket, block_bore (surfaces: every boundary face belongs to exactly one of
//   these; the liner-block contact faces are interior and belong to none).
//
// Parameter "size" = target element edge length [m]; documented size: coarse 0.009.
// Mesh by hand:  gmsh liner_block.geo -3 -order 2 -setnumber size 0.009 -o liner_block.msh
// A program overrides the size through onelab ("Parameters/size") before opening
// the file.  The element order is left to the loader on purpose.

SetFactory("OpenCASCADE");

DefineConstant[ size = {0.009, Name "Parameters/size"} ];

mm = 1e-3;

// ---- liner dimensions: exactly those of liner.geo ----------------------------------
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

// ---- block dimensions --------------------------------------------------------------
R_j    = 56.5*mm;          // water-jacket outer radius: jacket 7 mm wide radially
W      = 64.0*mm;          // half width of the square block (128 x 128 mm): outer wall 7.5 mm
z_b    = -175.0*mm;        // base face (bolted to the foundation), 15 mm below the liner
// Cavities of the block: counterbore radius R_f, h_f deep (holds the flange); upper bore R_u
// from -h_f to z_u; water jacket R_j from z_u to z_l (the deck is 18 mm thick over it); lower
// bore R_l from z_l through the base (open to the crankcase below the liner).  The liner fills
// the counterbore and both bores exactly, so after the fragments it shares the flange seat,
// the flange rim and both bands with the block (bonded joints).

// ---- liner: solid of revolution, profile in the (y, z) half-plane revolved about z ---
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
liner0 = rev[1];

// ---- block: box minus the counterbore, the bores and the jacket ---------------------
ext = 1.0*mm;   // tools overshoot the deck and the base (no coplanar cuts there)
box = newv; Box(box) = {-W, -W, z_b, 2*W, 2*W, -z_b};
t1 = newv; Cylinder(t1) = {0, 0, -h_f, 0, 0, h_f + ext, R_f};          // counterbore
t2 = newv; Cylinder(t2) = {0, 0, z_u, 0, 0, -h_f - z_u, R_u};          // upper bore
t3 = newv; Cylinder(t3) = {0, 0, z_l, 0, 0, z_u - z_l, R_j};           // water jacket
t4 = newv; Cylinder(t4) = {0, 0, z_b - ext, 0, 0, z_l - z_b + ext, R_l}; // lower bore
block0() = BooleanDifference{ Volume{box}; Delete; }{ Volume{t1, t2, t3, t4}; Delete; };

// ---- one conformal body: the contact faces become shared faces ----------------------
vols() = BooleanFragments{ Volume{liner0}; Delete; }{ Volume{block0()}; Delete; };
If (#vols() != 2)
  Error("liner_block.geo: expected 2 volumes after the fragments, got %g", #vols());
EndIf
liner = -1; block = -1;
For i In {0 : #vols() - 1}
  bb() = BoundingBox Volume{vols(i)};
  If (bb(3) > W - 5e-5)
    block = vols(i);
  Else
    liner = vols(i);
  EndIf
EndFor

// ---- physical groups: classify every boundary face of the union by its bounding box ---
tol = 5e-5;   // > OpenCASCADE bounding-box enlargement (~5 um), << feature sizes
bore() = {}; topf() = {}; botf() = {}; deck() = {}; outer() = {}; base() = {}; jack() = {};
bbore() = {}; other() = {};
bnd() = Abs(CombinedBoundary{ Volume{liner, block}; });
For i In {0 : #bnd() - 1}
  s = bnd(i);
  bb() = BoundingBox Surface{s};
  x0 = bb(0); y0 = bb(1); z0 = bb(2); x1 = bb(3); y1 = bb(4); z1 = bb(5);
  flat = (z1 - z0 < tol);
  If (!flat && (x1 - x0 < tol || y1 - y0 < tol))
    outer() += s;                                   // plane side walls x, y = +-W
  ElseIf (!flat && x1 < R_i + tol)
    bore() += s;
  ElseIf (flat && Fabs(z1) < tol && x1 < R_f + tol)
    topf() += s;
  ElseIf (flat && Fabs(z1) < tol)
    deck() += s;
  ElseIf (flat && Fabs(z1 - z_b) < tol)
    base() += s;
  ElseIf (flat && Fabs(z1 + L) < tol)
    botf() += s;
  ElseIf (z0 > z_l - tol && z1 < z_u + tol)
    jack() += s;                                    // liner and block walls of the jacket
  ElseIf (!flat && z1 < -L + tol && x1 < R_l + tol)
    bbore() += s;                                   // block bore below the liner
  Else
    other() += s;
  EndIf
EndFor
If (#other() > 0)
  Error("liner_block.geo: %g boundary faces fit no group", #other());
EndIf

Physical Volume("liner") = {liner};
Physical Volume("block") = {block};
Physical Surface("bore") = {bore()};
Physical Surface("top_face") = {topf()};
Physical Surface("bottom_face") = {botf()};
Physical Surface("deck") = {deck()};
Physical Surface("block_outer") = {outer()};
Physical Surface("base") = {base()};
Physical Surface("jacket") = {jack()};
Physical Surface("block_bore") = {bbore()};

// ---- mesh size --------------------------------------------------------------------
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = 0;
Mesh.Algorithm3D = 1;           // Delaunay: deterministic (HXT in Gmsh 4.8 is not)
Mesh.OptimizeThreshold = 0.6;   // optimise every tetrahedron of quality < 0.6 (default 0.3)
Mesh.HighOrderOptimize = 1;     // acts only if a curved element has a poor Jacobian ratio
