// A quarter of a solid ball for dyncontact's 3D meshes (read_gmsh_solid_mesh): the ball of radius
// R centred at (0, 0, CentreZ), cut to x >= 0, y >= 0 (all z), for a sphere dropped on a rigid
// plane modelled with the two symmetry planes x = 0 and y = 0. The contact pole is the lowest
// point (0, 0, CentreZ - R). Structured hexahedra only, from a "cubed sphere": in each of the two
// octants z >= CentreZ and z <= CentreZ (one conforming mesh, sharing the nodes on z = CentreZ),
// relative to the centre,
//   - an inner cube [0, a] x [0, a] x [0, +-a], a = 0.6 R / sqrt(3) (its outer corner 0.6 R
//     from the centre), with N equal cells along each edge;
//   - three shell blocks joining the cube's faces x = a, y = a, z = +-a to the sphere (the x-, y-
//     and z-shell), NR cells radially and N along each edge parallel to the cube. The shell
//     blocks meet on the planes x = y, x = +-(z - CentreZ), y = +-(z - CentreZ) through the
//     centre; their edges on the sphere are great-circle arcs between the points R(1, 0, 0),
//     R(1, 1, 0)/sqrt(2), R(1, 1, +-1)/sqrt(3), ... (8 volumes in all; the spherical patches lie
//     exactly on the sphere).
// Grading (PoleGrading > 1) refines the lower z-shell toward the contact pole: along the two
// sphere arcs from the pole toward R(1, 0, -1)/sqrt(2) and R(0, 1, -1)/sqrt(2) the cell edges
// grow geometrically away from the pole, and along the radial edge from (0, 0, -a) to the pole
// they shrink toward the pole, each by the factor PoleGrading from its smallest to its largest
// edge. Every other block edge stays uniform, the cube's too (grading its edges from (0, 0, -a)
// as well would put slender cells, smaller than the pole's, under the cube on the axis: longest /
// shortest edge 11 for N = 12, NR = 8, PoleGrading 4), and the blocks interpolate in between.
// With NR / N about 2/3 as in the defaults the cells at the pole are then about cubes (longest /
// shortest edge 1.35-1.6 for PoleGrading 3-10); the cube's cells (edge a / N = 0.35 R / N) are
// as small as the pole's for PoleGrading about 4 and larger beyond. The most slender cells are
// those of the lower z-shell on the axis next to the cube (small across, long radially: longest /
// shortest edge 4.5 for N = 6, NR = 4, PoleGrading 3; 5.3 and 8.3 for N = 12, NR = 8,
// PoleGrading 4 and 10). Where the graded arcs end (R(1, 0, -1)/sqrt(2), R(0, 1, -1)/sqrt(2))
// their last edge, PoleGrading times their first, meets the uniform edges of the x- and y-shell.
// PoleGrading = 1 is uniform along every block edge (longest / shortest edge <= 2.9 in every cell
// with the defaults). The cells at the cube's outer corners, where three shell blocks meet, have
// the smallest corner angles (scaled Jacobian 1/sqrt(3) = 0.58); grading keeps every other cell's
// above that for N >= 4 (N = 2, 3 with PoleGrading 10: down to 0.16, 0.46; N = 2 inverts cells
// from PoleGrading 18 on, hence the limit 10).
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R            sphere radius [length], > 0                                                 (8)
//   CentreZ      z of the centre [length]; the default puts the contact pole at z = 0        (8)
//   N            cells along each inner-cube edge and each shell-block edge parallel to the
//                cube (N per eighth of a great circle), integer >= 1                         (6)
//   NR           cells across each shell block radially (cube face to sphere), integer >= 1  (4)
//   PoleGrading  largest / smallest cell edge along each of the lower z-shell's edges graded
//                toward the contact pole (see above), 1 <= PoleGrading <= 10; 1 is uniform   (1)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Volume  1      the body (all 8 volumes)
//   Physical Surface 1      the symmetry plane x = 0 (a half disc)
//   Physical Surface 2      the symmetry plane y = 0 (a half disc)
//   Physical Surface 3      the sphere (a quarter of it; the contact surface)
// The faces inside the ball (cube faces, shell-block sides, the plane z = CentreZ) are in none.

DefineConstant[
  R = {8, Name "Parameters/R"}, CentreZ = {8, Name "Parameters/CentreZ"},
  N = {6, Name "Parameters/N"}, NR = {4, Name "Parameters/NR"},
  PoleGrading = {1, Name "Parameters/PoleGrading"}
];

If (R <= 0)
  Error("quarter_sphere_3d.geo: R = %g, but the radius must be > 0", R);
EndIf
If (N < 1 || N != Round(N) || NR < 1 || NR != Round(NR))
  Error("quarter_sphere_3d.geo: N = %g, NR = %g, but both must be integers >= 1", N, NR);
EndIf
If (PoleGrading < 1 || PoleGrading > 10)
  Error("quarter_sphere_3d.geo: PoleGrading = %g, but it must be in [1, 10]", PoleGrading);
EndIf

// The inner cube's edge, and the growth factors per cell edge of the graded edges
// (gmsh's Progression: each cell edge is the previous one times the factor).
a = 0.6 * R / Sqrt(3);
arc_growth = 1;
If (N > 1)
  arc_growth = PoleGrading^(1 / (N - 1));
EndIf
radial_growth = 1;
If (NR > 1)
  radial_growth = PoleGrading^(1 / (NR - 1));
EndIf

// The points on the plane z = CentreZ, shared by both octants: the centre (a corner of both
// cubes), the cube corners and the sphere points on the axes x, y and on the diagonal x = y.
zc = CentreZ;
p_o   = newp; Point(p_o)   = {0, 0, zc};
p_ca  = newp; Point(p_ca)  = {a, 0, zc};
p_cb  = newp; Point(p_cb)  = {0, a, zc};
p_cab = newp; Point(p_cab) = {a, a, zc};
p_sa  = newp; Point(p_sa)  = {R, 0, zc};
p_sb  = newp; Point(p_sb)  = {0, R, zc};
p_sab = newp; Point(p_sab) = {R / Sqrt(2), R / Sqrt(2), zc};

// Their edges: the cube's (from the centre outward, along x and y), the radial lines (cube to
// sphere) and the equator arcs toward the diagonal.
l_o_ca   = newl; Line(l_o_ca)   = {p_o, p_ca};
l_o_cb   = newl; Line(l_o_cb)   = {p_o, p_cb};
l_ca_cab = newl; Line(l_ca_cab) = {p_ca, p_cab};
l_cb_cab = newl; Line(l_cb_cab) = {p_cb, p_cab};
r_ca     = newl; Line(r_ca)     = {p_ca, p_sa};
r_cb     = newl; Line(r_cb)     = {p_cb, p_sb};
r_cab    = newl; Line(r_cab)    = {p_cab, p_sab};
a_sa_sab = newl; Circle(a_sa_sab) = {p_sa, p_o, p_sab};
a_sb_sab = newl; Circle(a_sb_sab) = {p_sb, p_o, p_sab};
Transfinite Curve {l_o_ca, l_o_cb, l_ca_cab, l_cb_cab, a_sa_sab, a_sb_sab} = N + 1;
Transfinite Curve {r_ca, r_cb, r_cab} = NR + 1;

// Their faces (inside the ball): the cube's, the x-shell's and the y-shell's on z = CentreZ.
ll = newll; Curve Loop(ll) = {l_o_ca, l_ca_cab, -l_cb_cab, -l_o_cb};
f_cube_mid = news; Plane Surface(f_cube_mid) = {ll};
ll = newll; Curve Loop(ll) = {r_ca, a_sa_sab, -r_cab, -l_ca_cab};
f_xshell_mid = news; Plane Surface(f_xshell_mid) = {ll};
ll = newll; Curve Loop(ll) = {r_cb, a_sb_sab, -r_cab, -l_cb_cab};
f_yshell_mid = news; Plane Surface(f_yshell_mid) = {ll};

volumes[] = {};
faces_x0[] = {};
faces_y0[] = {};
faces_sphere[] = {};
blocks_faces[] = {f_cube_mid, f_xshell_mid, f_yshell_mid};

// One octant, s = +1 (z >= CentreZ) or -1 (z <= CentreZ): set octant_side before each Call. Its
// points off the plane z = CentreZ: the cube corners at z = CentreZ + s a and the sphere points
// above (below) the equator's. The lower octant (s = -1) carries the grading toward the pole.
Macro QuarterBallOctant
  s = octant_side;
  grow_arc = 1;
  grow_radial = 1;
  If (s < 0)
    grow_arc = arc_growth;
    grow_radial = radial_growth;
  EndIf

  p_z    = newp; Point(p_z)    = {0, 0, zc + s * a};
  p_za   = newp; Point(p_za)   = {a, 0, zc + s * a};
  p_zb   = newp; Point(p_zb)   = {0, a, zc + s * a};
  p_zab  = newp; Point(p_zab)  = {a, a, zc + s * a};
  p_sz   = newp; Point(p_sz)   = {0, 0, zc + s * R};
  p_sza  = newp; Point(p_sza)  = {R / Sqrt(2), 0, zc + s * R / Sqrt(2)};
  p_szb  = newp; Point(p_szb)  = {0, R / Sqrt(2), zc + s * R / Sqrt(2)};
  p_szab = newp; Point(p_szab) = {R / Sqrt(3), R / Sqrt(3), zc + s * R / Sqrt(3)};

  // The cube's edges along z (from z = CentreZ) and on its face z = CentreZ + s a (from the
  // axis outward, along x and y).
  v_o      = newl; Line(v_o)      = {p_o, p_z};
  v_ca     = newl; Line(v_ca)     = {p_ca, p_za};
  v_cb     = newl; Line(v_cb)     = {p_cb, p_zb};
  v_cab    = newl; Line(v_cab)    = {p_cab, p_zab};
  l_z_za   = newl; Line(l_z_za)   = {p_z, p_za};
  l_z_zb   = newl; Line(l_z_zb)   = {p_z, p_zb};
  l_za_zab = newl; Line(l_za_zab) = {p_za, p_zab};
  l_zb_zab = newl; Line(l_zb_zab) = {p_zb, p_zab};
  // The radial lines, from the cube to the sphere.
  r_z   = newl; Line(r_z)   = {p_z, p_sz};
  r_za  = newl; Line(r_za)  = {p_za, p_sza};
  r_zb  = newl; Line(r_zb)  = {p_zb, p_szb};
  r_zab = newl; Line(r_zab) = {p_zab, p_szab};
  // The great-circle arcs: from the equator toward the pole, and from the pole outward.
  a_sa_sza   = newl; Circle(a_sa_sza)   = {p_sa, p_o, p_sza};
  a_sb_szb   = newl; Circle(a_sb_szb)   = {p_sb, p_o, p_szb};
  a_sab_szab = newl; Circle(a_sab_szab) = {p_sab, p_o, p_szab};
  a_sz_sza   = newl; Circle(a_sz_sza)   = {p_sz, p_o, p_sza};
  a_sz_szb   = newl; Circle(a_sz_szb)   = {p_sz, p_o, p_szb};
  a_sza_szab = newl; Circle(a_sza_szab) = {p_sza, p_o, p_szab};
  a_szb_szab = newl; Circle(a_szb_szab) = {p_szb, p_o, p_szab};

  Transfinite Curve {v_o, v_ca, v_cb, v_cab, l_za_zab, l_zb_zab} = N + 1;
  Transfinite Curve {a_sa_sza, a_sb_szb, a_sab_szab, a_sza_szab, a_szb_szab} = N + 1;
  Transfinite Curve {r_za, r_zb, r_zab} = NR + 1;
  Transfinite Curve {l_z_za, l_z_zb} = N + 1;
  // Graded in the lower octant: the arcs are oriented away from the pole and grow away from it;
  // the radial line is oriented toward the pole and shrinks toward it.
  Transfinite Curve {a_sz_sza, a_sz_szb} = N + 1 Using Progression grow_arc;
  Transfinite Curve {r_z} = NR + 1 Using Progression 1 / grow_radial;

  // The cube's faces: x = 0, y = 0, x = a, y = a, z = CentreZ + s a.
  ll = newll; Curve Loop(ll) = {l_o_cb, v_cb, -l_z_zb, -v_o};
  f_cube_x0 = news; Plane Surface(f_cube_x0) = {ll};
  ll = newll; Curve Loop(ll) = {l_o_ca, v_ca, -l_z_za, -v_o};
  f_cube_y0 = news; Plane Surface(f_cube_y0) = {ll};
  ll = newll; Curve Loop(ll) = {l_ca_cab, v_cab, -l_za_zab, -v_ca};
  f_cube_xa = news; Plane Surface(f_cube_xa) = {ll};
  ll = newll; Curve Loop(ll) = {l_cb_cab, v_cab, -l_zb_zab, -v_cb};
  f_cube_ya = news; Plane Surface(f_cube_ya) = {ll};
  ll = newll; Curve Loop(ll) = {l_z_za, l_za_zab, -l_zb_zab, -l_z_zb};
  f_cube_za = news; Plane Surface(f_cube_za) = {ll};

  // The shell blocks' sides inside the ball: on x = y (x- and y-shell), on x = s (z - CentreZ)
  // (x- and z-shell), on y = s (z - CentreZ) (y- and z-shell).
  ll = newll; Curve Loop(ll) = {r_cab, a_sab_szab, -r_zab, -v_cab};
  f_xy = news; Plane Surface(f_xy) = {ll};
  ll = newll; Curve Loop(ll) = {r_za, a_sza_szab, -r_zab, -l_za_zab};
  f_xz = news; Plane Surface(f_xz) = {ll};
  ll = newll; Curve Loop(ll) = {r_zb, a_szb_szab, -r_zab, -l_zb_zab};
  f_yz = news; Plane Surface(f_yz) = {ll};

  // The shell blocks' sides on the symmetry planes: the x-shell's on y = 0, the y-shell's on
  // x = 0, the z-shell's on both.
  ll = newll; Curve Loop(ll) = {r_ca, a_sa_sza, -r_za, -v_ca};
  f_xshell_y0 = news; Plane Surface(f_xshell_y0) = {ll};
  ll = newll; Curve Loop(ll) = {r_cb, a_sb_szb, -r_zb, -v_cb};
  f_yshell_x0 = news; Plane Surface(f_yshell_x0) = {ll};
  ll = newll; Curve Loop(ll) = {r_z, a_sz_szb, -r_zb, -l_z_zb};
  f_zshell_x0 = news; Plane Surface(f_zshell_x0) = {ll};
  ll = newll; Curve Loop(ll) = {r_z, a_sz_sza, -r_za, -l_z_za};
  f_zshell_y0 = news; Plane Surface(f_zshell_y0) = {ll};

  // The spherical patches of the x-, y- and z-shell, on the sphere exactly.
  ll = newll; Curve Loop(ll) = {a_sa_sab, a_sab_szab, -a_sza_szab, -a_sa_sza};
  f_xshell_sphere = news; Surface(f_xshell_sphere) = {ll} In Sphere {p_o};
  ll = newll; Curve Loop(ll) = {a_sb_sab, a_sab_szab, -a_szb_szab, -a_sb_szb};
  f_yshell_sphere = news; Surface(f_yshell_sphere) = {ll} In Sphere {p_o};
  ll = newll; Curve Loop(ll) = {a_sz_sza, a_sza_szab, -a_szb_szab, -a_sz_szb};
  f_zshell_sphere = news; Surface(f_zshell_sphere) = {ll} In Sphere {p_o};

  // The four blocks.
  sl = newsl;
  Surface Loop(sl) = {f_cube_mid, f_cube_x0, f_cube_y0, f_cube_xa, f_cube_ya, f_cube_za};
  v_cube = newv; Volume(v_cube) = {sl};
  sl = newsl;
  Surface Loop(sl) = {f_cube_xa, f_xshell_sphere, f_xshell_y0, f_xshell_mid, f_xy, f_xz};
  v_xshell = newv; Volume(v_xshell) = {sl};
  sl = newsl;
  Surface Loop(sl) = {f_cube_ya, f_yshell_sphere, f_yshell_x0, f_yshell_mid, f_xy, f_yz};
  v_yshell = newv; Volume(v_yshell) = {sl};
  sl = newsl;
  Surface Loop(sl) = {f_cube_za, f_zshell_sphere, f_zshell_x0, f_zshell_y0, f_xz, f_yz};
  v_zshell = newv; Volume(v_zshell) = {sl};

  volumes[] += {v_cube, v_xshell, v_yshell, v_zshell};
  faces_x0[] += {f_cube_x0, f_yshell_x0, f_zshell_x0};
  faces_y0[] += {f_cube_y0, f_xshell_y0, f_zshell_y0};
  faces_sphere[] += {f_xshell_sphere, f_yshell_sphere, f_zshell_sphere};
  blocks_faces[] += {f_cube_x0, f_cube_y0, f_cube_xa, f_cube_ya, f_cube_za, f_xy, f_xz, f_yz,
    f_xshell_y0, f_yshell_x0, f_zshell_x0, f_zshell_y0,
    f_xshell_sphere, f_yshell_sphere, f_zshell_sphere};
Return

octant_side = 1;
Call QuarterBallOctant;
octant_side = -1;
Call QuarterBallOctant;

Transfinite Surface {blocks_faces[]};
Recombine Surface {blocks_faces[]};
Transfinite Volume {volumes[]};
Recombine Volume {volumes[]};

Physical Volume("ball", 1)   = {volumes[]};
Physical Surface("x0", 1)    = {faces_x0[]};
Physical Surface("y0", 2)    = {faces_y0[]};
Physical Surface("sphere", 3) = {faces_sphere[]};
