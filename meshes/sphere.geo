// Axisymmetric sphere for dyncontact: the half disc r >= 0 of radius R in the (r, z) plane, gmsh
// coordinates x = r, y = z. All quadrilaterals, from a transfinite "O-grid" (the classic quarter-
// disc layout mirrored to the half disc): a core quadrilateral on the axis, inside the square
// [0, a] x [z_c - a, z_c + a] (a = 0.45 R), surrounded by three curved blocks that reach the
// sphere surface: the pole block, the side block across the equator and the far block.
//
// The contact pole is the point of the surface on the axis that faces the other body:
// z = CentreZ + PoleSide * R. Along the surface the element edges grow geometrically, by one
// factor, from the contact pole to the far pole, so the smallest elements sit where contact
// happens; the block corners on the surface sit where that series puts them (at +-45 degrees
// from the equator only for PoleGrading = 1), and the core corners on the same rays. Along every
// radial line the elements shrink toward the surface.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R               sphere radius [length], > 0                                           (8)
//   CentreZ         z of the centre [length]                                              (0)
//   PoleSide        +1: contact pole at z = CentreZ + R (body 1 of dyncontact), -1: at
//                   z = CentreZ - R (the mirror image)                                    (1)
//   Divisions       element edges on the surface of the pole block at refinement 0, integer
//                   >= 1; the half circumference has 4 * Divisions edges                  (6)
//   RadialDivisions element layers between the core and the surface, integer >= 1        (6)
//   Refinement      each level doubles Divisions and RadialDivisions, integer >= 0        (0)
//   PoleGrading     largest / smallest element edge along the surface (far pole / contact
//                   pole), >= 1; 1 is uniform; beyond about 10 the pole block is slender  (3)
//   SurfaceGrading  innermost / outermost element layer along each radial line, >= 1      (1.5)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Surface 1      the body
//   Physical Curve   1      the axis r = 0
//   Physical Curve   2      the sphere surface
//
// two_spheres.geo includes this file with SphereMacroOnly = 1 and calls the macro SphereBody
// itself, once per body, so the two bodies are built from exactly the same transfinite data.

DefineConstant[
  R               = {8,   Name "Parameters/R"},
  Divisions       = {6,   Name "Parameters/Divisions"},
  RadialDivisions = {6,   Name "Parameters/RadialDivisions"},
  Refinement      = {0,   Name "Parameters/Refinement"},
  PoleGrading     = {3,   Name "Parameters/PoleGrading"},
  SurfaceGrading  = {1.5, Name "Parameters/SurfaceGrading"}
];

If (R <= 0)
  Error("sphere.geo: R = %g, but the radius must be > 0", R);
EndIf
If (Divisions < 1 || Divisions != Round(Divisions))
  Error("sphere.geo: Divisions = %g, but it must be an integer >= 1", Divisions);
EndIf
If (RadialDivisions < 1 || RadialDivisions != Round(RadialDivisions))
  Error("sphere.geo: RadialDivisions = %g, but it must be an integer >= 1", RadialDivisions);
EndIf
If (Refinement < 0 || Refinement != Round(Refinement))
  Error("sphere.geo: Refinement = %g, but it must be an integer >= 0", Refinement);
EndIf
If (PoleGrading < 1)
  Error("sphere.geo: PoleGrading = %g, but it must be >= 1", PoleGrading);
EndIf
If (SurfaceGrading < 1)
  Error("sphere.geo: SurfaceGrading = %g, but it must be >= 1", SurfaceGrading);
EndIf

// Element edges on the surface arc of the pole block (and of the far block; twice as many on the
// side block), and element layers radially.
n_arc    = Divisions * 2^Refinement;
n_radial = RadialDivisions * 2^Refinement;

// Growth factor per element edge: along the surface (4 n_arc edges from pole to pole), and inward
// along the radial lines.
arc_growth    = PoleGrading^(1 / (4 * n_arc - 1));
radial_growth = 1;
If (n_radial > 1)
  radial_growth = SurfaceGrading^(1 / (n_radial - 1));
EndIf

// Angles from the contact pole of the surface block corners: after n_arc edges (pole block) and
// after 3 n_arc edges (pole and side block) of the geometric series.
If (arc_growth > 1)
  pole_corner_angle = Pi * (arc_growth^n_arc - 1) / (arc_growth^(4 * n_arc) - 1);
  far_corner_angle  = Pi * (arc_growth^(3 * n_arc) - 1) / (arc_growth^(4 * n_arc) - 1);
Else
  pole_corner_angle = Pi / 4;
  far_corner_angle  = 3 * Pi / 4;
EndIf

// The core corners: where the rays from the centre to the surface corners leave the square
// [0, a] x [-a, a] (local coordinates r and t, see the macro).
core_size        = 0.45 * R;
pole_core_radius = core_size / Max(Sin(pole_corner_angle), Fabs(Cos(pole_corner_angle)));
far_core_radius  = core_size / Max(Sin(far_corner_angle), Fabs(Cos(far_corner_angle)));

// One sphere: the centre (0, sphere_centre_z), contact pole at sphere_centre_z + sphere_pole_side
// R, physical surface sphere_body and physical curve 1 + sphere_body for its surface; its axis
// curves are appended to axis_curves[]. Local coordinate t along the axis toward the contact
// pole: z = sphere_centre_z + sphere_pole_side * t.
Macro SphereBody
  s  = sphere_pole_side;
  zc = sphere_centre_z;

  centre = newp; Point(centre) = {0, zc, 0};

  core_axis_pole   = newp;
  Point(core_axis_pole) = {0, zc + s * core_size, 0};
  core_corner_pole = newp;
  Point(core_corner_pole) = {pole_core_radius * Sin(pole_corner_angle),
                             zc + s * pole_core_radius * Cos(pole_corner_angle), 0};
  core_corner_far  = newp;
  Point(core_corner_far) = {far_core_radius * Sin(far_corner_angle),
                            zc + s * far_core_radius * Cos(far_corner_angle), 0};
  core_axis_far    = newp;
  Point(core_axis_far) = {0, zc - s * core_size, 0};

  surface_pole        = newp;
  Point(surface_pole) = {0, zc + s * R, 0};
  surface_corner_pole = newp;
  Point(surface_corner_pole) = {R * Sin(pole_corner_angle), zc + s * R * Cos(pole_corner_angle), 0};
  surface_corner_far  = newp;
  Point(surface_corner_far) = {R * Sin(far_corner_angle), zc + s * R * Cos(far_corner_angle), 0};
  surface_far         = newp;
  Point(surface_far) = {0, zc - s * R, 0};

  // Surface arcs and the core edges opposite them, all oriented from the contact pole toward the
  // far pole, so one growth factor grades them all; the arcs continue one geometric series.
  arc_pole = newl; Circle(arc_pole) = {surface_pole, centre, surface_corner_pole};
  arc_side = newl; Circle(arc_side) = {surface_corner_pole, centre, surface_corner_far};
  arc_far  = newl; Circle(arc_far)  = {surface_corner_far, centre, surface_far};
  core_pole = newl; Line(core_pole) = {core_axis_pole, core_corner_pole};
  core_side = newl; Line(core_side) = {core_corner_pole, core_corner_far};
  core_far  = newl; Line(core_far)  = {core_corner_far, core_axis_far};
  axis_core = newl; Line(axis_core) = {core_axis_pole, core_axis_far};

  // Radial lines, oriented from the core outward.
  axis_pole   = newl; Line(axis_pole)   = {core_axis_pole, surface_pole};
  radial_pole = newl; Line(radial_pole) = {core_corner_pole, surface_corner_pole};
  radial_far  = newl; Line(radial_far)  = {core_corner_far, surface_corner_far};
  axis_far    = newl; Line(axis_far)    = {core_axis_far, surface_far};

  Transfinite Curve {arc_pole, core_pole, arc_far, core_far} = n_arc + 1
    Using Progression arc_growth;
  Transfinite Curve {arc_side, core_side, axis_core} = 2 * n_arc + 1
    Using Progression arc_growth;
  Transfinite Curve {axis_pole, radial_pole, radial_far, axis_far} = n_radial + 1
    Using Progression 1 / radial_growth;

  core_loop = newll; Curve Loop(core_loop) = {core_pole, core_side, core_far, -axis_core};
  pole_loop = newll; Curve Loop(pole_loop) = {axis_pole, arc_pole, -radial_pole, -core_pole};
  side_loop = newll; Curve Loop(side_loop) = {radial_pole, arc_side, -radial_far, -core_side};
  far_loop  = newll; Curve Loop(far_loop)  = {radial_far, arc_far, -axis_far, -core_far};

  core_block = news; Plane Surface(core_block) = {core_loop};
  pole_block = news; Plane Surface(pole_block) = {pole_loop};
  side_block = news; Plane Surface(side_block) = {side_loop};
  far_block  = news; Plane Surface(far_block)  = {far_loop};

  blocks[] = {core_block, pole_block, side_block, far_block};
  Transfinite Surface {blocks[]};
  Recombine Surface {blocks[]};

  Physical Surface(Sprintf("body %g", sphere_body), sphere_body) = {blocks[]};
  Physical Curve(Sprintf("surface of body %g", sphere_body), 1 + sphere_body) =
    {arc_pole, arc_side, arc_far};
  axis_curves[] += {axis_pole, axis_core, axis_far};
Return

axis_curves[] = {};

If (!Exists(SphereMacroOnly))
  DefineConstant[
    CentreZ  = {0, Name "Parameters/CentreZ"},
    PoleSide = {1, Name "Parameters/PoleSide"}
  ];
  If (PoleSide != 1 && PoleSide != -1)
    Error("sphere.geo: PoleSide = %g, but only +1 and -1 are allowed", PoleSide);
  EndIf
  sphere_centre_z  = CentreZ;
  sphere_pole_side = PoleSide;
  sphere_body      = 1;
  Call SphereBody;
  Physical Curve("axis", 1) = {axis_curves[]};
EndIf
