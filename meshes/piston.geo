// piston.geo -- parametric piston of the flexehd example engine (bore 86 mm).
//
// Units: metres.  Frame: origin at the centre of the pin axis, z = cylinder axis
// (positive towards the cylinder head, crown at z > 0, skirt bottom at z < 0),
// +x = major thrust side, y = pin axis.  Dimensions, their sources, the physical
// groups and measured mesh statistics are documented in docs/meshes.md.
//
// Physical groups (every boundary face belongs to exactly one surface group):
//   piston (volume); crown, ring_lands, ring_grooves, skirt, skirt_taper,
//   pin_bore, underside (surfaces).
//
// Parameter "size" = target element edge length [m]; documented sizes:
//   coarse 0.0065, default 0.004, production 0.0025.
// Mesh by hand:  gmsh piston.geo -3 -order 2 -setnumber size 0.004 -o piston.msh
// A program overrides the size through onelab ("Parameters/size") before opening
// the file.  The element order is left to the loader on purpose.

SetFactory("OpenCASCADE");

DefineConstant[ size = {0.004, Name "Parameters/size"} ];

mm = 1e-3;

// ---- main dimensions ----------------------------------------------------------
D       = 86.0*mm;            // bore
c_sk    = 50e-6;              // nominal radial skirt clearance (seed paper)
R_sk    = D/2 - c_sk;         // skirt outer radius
R_top   = D/2 - 0.45*mm;      // top land radius
R_land  = D/2 - 0.30*mm;      // 2nd, 3rd land and the band below the oil groove
d_grv   = 3.5*mm;             // ring groove depth, measured from R_land
R_root  = R_land - d_grv;     // groove root radius

KH      = 33.0*mm;            // compression height: pin axis -> crown top
h_top   = 6.5*mm;             // top land height
w_g1    = 1.2*mm;             // compression ring groove width
h_l2    = 4.0*mm;             // second land height
w_g2    = 1.5*mm;             // second (scraper) ring groove width
h_l3    = 3.5*mm;             // third land height
w_g3    = 2.5*mm;             // oil control ring groove width
h_band  = 1.5*mm;             // full-circumference band below the oil groove

t_crown = 6.0*mm;             // crown thickness
R_cav   = 36.0*mm;            // radius of the cavity under the crown

z_sb    = -25.0*mm;           // skirt bottom
t_sk    = 3.0*mm;             // skirt panel wall thickness
h_ch    = 1.5*mm;             // axial length of the taper at the skirt top
Y_e     = 27.5*mm;            // skirt panel half-width (|y| <= Y_e): about +-40 deg
t_w     = 3.5*mm;             // side wall thickness (box-type piston)
z_wb    = -20.0*mm;           // bottom of the side walls

R_pin   = 10.5*mm;            // pin bore radius (pin diameter 21 mm)
R_boss  = 16.5*mm;            // pin boss outer radius
y_bi    = 13.0*mm;            // inner boss face (boss spacing 26 mm)
y_bo    = 37.0*mm;            // outer boss face (pin length ~74 mm)
b_web   = 8.0*mm;             // half-width of the boss web at the crown underside

// ---- derived axial stations ---------------------------------------------------
z_g1t = KH - h_top;    z_g1b = z_g1t - w_g1;
z_g2t = z_g1b - h_l2;  z_g2b = z_g2t - w_g2;
z_g3t = z_g2b - h_l3;  z_g3b = z_g3t - w_g3;
z_rb  = z_g3b - h_band;          // bottom of the ring belt = top of the skirt
z_cu  = KH - t_crown;            // crown underside
R_in  = R_sk - t_sk;             // skirt panel inner radius
big   = 60*mm;                   // "large" extent for cutting tools
ov    = 1.0*mm;                  // overlap of fused parts (no touching faces)

// ---- crown and ring belt: solid cylinder minus the cavity ---------------------
c_belt = newv; Cylinder(c_belt) = {0,0,z_rb, 0,0,KH - z_rb, R_land};
c_cav = newv; Cylinder(c_cav) = {0,0,z_rb - ov, 0,0,z_cu - z_rb + ov, R_cav};
belt() = BooleanDifference{ Volume{c_belt}; Delete; }{ Volume{c_cav}; Delete; };

// ---- skirt panels: annulus restricted to |y| <= Y_e (two panels, +-x) ----------
// Profile in the (y, z) half-plane, revolved about z (the seam then lies at +y,
// where there is no panel).  The top h_ch of the panel tapers from R_sk to R_land
// so that the skirt joins the band below the oil groove without a step.
q1 = newp; Point(q1) = {0, R_in, z_sb};
q2 = newp; Point(q2) = {0, R_sk, z_sb};
q3 = newp; Point(q3) = {0, R_sk, z_rb - h_ch};
q4 = newp; Point(q4) = {0, R_land, z_rb};
q5 = newp; Point(q5) = {0, R_in, z_rb};
k1 = newl; Line(k1) = {q1,q2};
k2 = newl; Line(k2) = {q2,q3};
k3 = newl; Line(k3) = {q3,q4};
k4 = newl; Line(k4) = {q4,q5};
k5 = newl; Line(k5) = {q5,q1};
kl = newll; Curve Loop(kl) = {k1,k2,k3,k4,k5};
ks = news; Plane Surface(ks) = {kl};
ann[] = Extrude {{0,0,1}, {0,0,0}, 2*Pi} { Surface{ks}; };
Recursive Delete { Surface{ks}; }   // the profile is not part of the closed solid
b_panel = newv; Box(b_panel) = {-big, -Y_e, z_sb - ov, 2*big, 2*Y_e, z_rb - z_sb + 2*ov};
panels() = BooleanIntersection{ Volume{ann[1]}; Delete; }{ Volume{b_panel}; Delete; };

// ---- side walls joining the panel edges, through the bosses --------------------
c_wall1 = newv; Cylinder(c_wall1) = {0,0,z_wb, 0,0,z_cu + ov - z_wb, R_in + ov};
b_wall1 = newv; Box(b_wall1) = {-big, Y_e - t_w, z_wb - ov, 2*big, t_w, z_cu - z_wb + 3*ov};
wall1() = BooleanIntersection{ Volume{c_wall1}; Delete; }{ Volume{b_wall1}; Delete; };
c_wall2 = newv; Cylinder(c_wall2) = {0,0,z_wb, 0,0,z_cu + ov - z_wb, R_in + ov};
b_wall2 = newv; Box(b_wall2) = {-big, -Y_e, z_wb - ov, 2*big, t_w, z_cu - z_wb + 3*ov};
wall2() = BooleanIntersection{ Volume{c_wall2}; Delete; }{ Volume{b_wall2}; Delete; };

// ---- boss support: solid between the walls and the ring belt at the pin sides --
// (the under-crown cavity is bounded by the side walls, |y| < Y_e - t_w)
c_fill1 = newv; Cylinder(c_fill1) = {0,0,z_rb, 0,0,z_cu + ov - z_rb, R_cav + ov};
b_fill1 = newv; Box(b_fill1) = {-big, Y_e - t_w, z_rb - ov, 2*big, big, z_cu - z_rb + 3*ov};
fill1() = BooleanIntersection{ Volume{c_fill1}; Delete; }{ Volume{b_fill1}; Delete; };
c_fill2 = newv; Cylinder(c_fill2) = {0,0,z_rb, 0,0,z_cu + ov - z_rb, R_cav + ov};
b_fill2 = newv; Box(b_fill2) = {-big, -big - (Y_e - t_w), z_rb - ov, 2*big, big, z_cu - z_rb + 3*ov};
fill2() = BooleanIntersection{ Volume{c_fill2}; Delete; }{ Volume{b_fill2}; Delete; };

// ---- pin bosses: cylinder about y plus a tapered web up to the crown underside -
c_boss1 = newv; Cylinder(c_boss1) = {0, y_bi, 0, 0, y_bo - y_bi, 0, R_boss};
c_boss2 = newv; Cylinder(c_boss2) = {0, -y_bi, 0, 0, -(y_bo - y_bi), 0, R_boss};
p1 = newp; Point(p1)   = {-R_boss, 0, 0};
p2 = newp; Point(p2)   = { R_boss, 0, 0};
p3 = newp; Point(p3)   = { b_web,  0, z_cu + ov};
p4 = newp; Point(p4)   = {-b_web,  0, z_cu + ov};
l1 = newl; Line(l1) = {p1,p2};
l2 = newl; Line(l2) = {p2,p3};
l3 = newl; Line(l3) = {p3,p4};
l4 = newl; Line(l4) = {p4,p1};
cl = newll; Curve Loop(cl) = {l1,l2,l3,l4};
sw = news; Plane Surface(sw) = {cl};
web1[] = Extrude {0, y_bo - y_bi, 0} { Surface{sw}; };
Translate {0, y_bi, 0} { Volume{web1[1]}; }
web2[] = Rotate {{0,0,1}, {0,0,0}, Pi} { Duplicata { Volume{web1[1]}; } };

body() = BooleanUnion{ Volume{belt()}; Delete; }
                     { Volume{panels(), wall1(), wall2(), fill1(), fill2(), c_boss1, c_boss2, web1[1], web2[0]}; Delete; };

// ---- cutting tools: ring grooves, top land relief, pin bore --------------------
c_g1o = newv; Cylinder(c_g1o) = {0,0,z_g1b, 0,0,w_g1, big};
c_g1i = newv; Cylinder(c_g1i) = {0,0,z_g1b - ov, 0,0,w_g1 + 2*ov, R_root};
g1() = BooleanDifference{ Volume{c_g1o}; Delete; }{ Volume{c_g1i}; Delete; };
c_g2o = newv; Cylinder(c_g2o) = {0,0,z_g2b, 0,0,w_g2, big};
c_g2i = newv; Cylinder(c_g2i) = {0,0,z_g2b - ov, 0,0,w_g2 + 2*ov, R_root};
g2() = BooleanDifference{ Volume{c_g2o}; Delete; }{ Volume{c_g2i}; Delete; };
c_g3o = newv; Cylinder(c_g3o) = {0,0,z_g3b, 0,0,w_g3, big};
c_g3i = newv; Cylinder(c_g3i) = {0,0,z_g3b - ov, 0,0,w_g3 + 2*ov, R_root};
g3() = BooleanDifference{ Volume{c_g3o}; Delete; }{ Volume{c_g3i}; Delete; };
c_tlo = newv; Cylinder(c_tlo) = {0,0,z_g1t - 0.5*w_g1, 0,0,KH - z_g1t + 0.5*w_g1 + ov, big};
c_tli = newv; Cylinder(c_tli) = {0,0,z_g1t - w_g1, 0,0,KH - z_g1t + w_g1 + 2*ov, R_top};
tl() = BooleanDifference{ Volume{c_tlo}; Delete; }{ Volume{c_tli}; Delete; };
c_pin = newv; Cylinder(c_pin) = {0, -big, 0, 0, 2*big, 0, R_pin};

piston() = BooleanDifference{ Volume{body()}; Delete; }
                            { Volume{g1(), g2(), g3(), tl(), c_pin}; Delete; };

// ---- physical groups: classify every boundary face by its bounding box --------
tol = 5e-5;   // > OpenCASCADE bounding-box enlargement (~5 um), << feature sizes
crown() = {}; lands() = {}; grooves() = {}; skirt() = {}; pinb() = {}; under() = {}; taper() = {};
bnd() = Abs(Boundary{ Volume{piston()}; });
For i In {0 : #bnd() - 1}
  s = bnd(i);
  bb() = BoundingBox Surface{s};
  x0 = bb(0); y0 = bb(1); z0 = bb(2); x1 = bb(3); y1 = bb(4); z1 = bb(5);
  flat = (z1 - z0 < tol);                            // normal to z
  full = (x0 < -R_root + tol && x1 > R_root - tol);  // spans the whole circumference
  If (flat && Fabs(z1 - KH) < tol)
    crown() += s;
  ElseIf (full && z0 > z_g1b - tol && z1 < z_g1t + tol)
    grooves() += s;
  ElseIf (full && z0 > z_g2b - tol && z1 < z_g2t + tol)
    grooves() += s;
  ElseIf (full && z0 > z_g3b - tol && z1 < z_g3t + tol)
    grooves() += s;
  ElseIf (!flat && x0 > -R_pin - tol && x1 < R_pin + tol && z0 > -R_pin - tol && z1 < R_pin + tol)
    pinb() += s;
  ElseIf (!flat && (x1 > (R_sk + R_land)/2 || x0 < -(R_sk + R_land)/2) && z1 < z_rb - h_ch + tol)
    skirt() += s;
  ElseIf (!flat && (x1 > (R_sk + R_land)/2 || x0 < -(R_sk + R_land)/2))
    taper() += s;
  ElseIf (!flat && full && z0 > z_rb - tol)
    lands() += s;
  Else
    under() += s;
  EndIf
EndFor

Physical Volume("piston") = {piston()};
Physical Surface("crown") = {crown()};
Physical Surface("ring_lands") = {lands()};
Physical Surface("ring_grooves") = {grooves()};
Physical Surface("skirt") = {skirt()};
Physical Surface("skirt_taper") = {taper()};
Physical Surface("pin_bore") = {pinb()};
Physical Surface("underside") = {under()};

// ---- mesh size ------------------------------------------------------------
// One parameter: the target element edge length.  No local refinement is needed:
// the short curves (groove widths, skirt taper) get single element edges and the
// mesh grades away from them.  Every documented size was checked for positive
// Jacobians of the 10-node tetrahedra (docs/meshes.md).
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = 0;
Mesh.Algorithm3D = 1;           // Delaunay: deterministic (HXT in Gmsh 4.8 is not)
Mesh.OptimizeThreshold = 0.6;   // optimise every tetrahedron of quality < 0.6 (default 0.3)
Mesh.HighOrderOptimize = 1;     // acts only if a curved element has a poor Jacobian ratio
