// Axisymmetric sphere for dyncontact: the half disc r >= 0 of radius R in the (r, z) plane, gmsh
// coordinates x = r, y = z. All quadrilaterals, from a transfinite "O-grid" (the classic quarter-
// disc layout mirrored to the half disc): a core quadrilateral on the axis, inside the square
// [0, a] x [z_0 - a, z_0 + a] (a = 0.45 R, z_0 = CentreZ + PoleSide * CoreOffset * R: the centre,
// or shifted toward the contact pole), surrounded by three curved blocks that reach the sphere
// surface: the pole block, the side block across the equator and the far block.
//
// The contact pole is the point of the surface on the axis that faces the other body:
// z = CentreZ + PoleSide * R. Along the surface the element edges grow geometrically, by one
// factor, from the contact pole to the far pole, so the smallest elements sit where contact
// happens; the block corners on the surface sit where that series puts them (at +-45 degrees
// from the equator only for PoleGrading = 1), and the core corners on the rays from (0, z_0) to
// them. Along every radial line the elements shrink toward the surface.
//
// Strong grading (PoleGrading about 10) narrows the pole block to a few degrees, so with the core
// centred its elements near the core turn slender (aspect ratio 7-9); CoreOffset 0.3 shortens the
// pole block radially and keeps every element compact. A graded family that halves the element
// edges near the contact pole at each level: Refinement 0, 1, 2 with PoleGrading 10 and
// CoreOffset 0.3 (with R = 8: smallest surface edge 0.26, 0.13, 0.067; aspect ratio <= 2.9).
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
//                   pole), >= 1; 1 is uniform; beyond about 10 the pole block is slender
//                   unless CoreOffset is about 0.3                                        (3)
//   SurfaceGrading  innermost / outermost element layer along each radial line, >= 1      (1.5)
//   CoreOffset      shift of the core toward the contact pole, as a fraction of R,
//                   0 <= CoreOffset <= 0.5; 0 centres it on the sphere's centre           (0)
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
  SurfaceGrading  = {1.5, Name "Parameters/SurfaceGrading"},
  CoreOffset      = {0,   Name "Parameters/CoreOffset"}
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
If (CoreOffset < 0 || CoreOffset > 0.5)
  Error("sphere.geo: CoreOffset = %g, but it must be in [0, 0.5]", CoreOffset);
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

// The core corners: where the rays from the core's centre (0, core_offset) to the surface corners
// leave the square [0, a] x [core_offset - a, core_offset + a] (local coordinates r and t, see
// the macro). A ray is (0, core_offset) + c (Sin(angle), Cos(angle) - CoreOffset), c >= 0, and
// c at the corner is its core_fraction (CoreOffset = 0: the corner's distance from the centre).
core_size          = 0.45 * R;
core_offset        = CoreOffset * R;
pole_core_fraction =
  core_size / Max(Sin(pole_corner_angle), Fabs(Cos(pole_corner_angle) - CoreOffset));
far_core_fraction  =
  core_size / Max(Sin(far_corner_angle), Fabs(Cos(far_corner_angle) - CoreOffset));

// One sphere: the centre (0, sphere_centre_z), contact pole at sphere_centre_z + sphere_pole_side
// R, physical surface sphere_body and physical curve 1 + sphere_body for its surface; its axis
// curves are appended to axis_curves[]. Local coordinate t along the axis toward the contact
// pole: z = sphere_centre_z + sphere_pole_side * t.
Macro SphereBody
  s  = sphere_pole_side;
  zc = sphere_centre_z;

  centre = newp; Point(centre) = {0, zc, 0};

  core_axis_pole   = newp;
  Point(core_axis_pole) = {0, zc + s * (core_offset + core_size), 0};
  core_corner_pole = newp;
  Point(core_corner_pole) = {pole_core_fraction * Sin(pole_corner_angle),
    zc + s * (core_offset + pole_core_fraction * (Cos(pole_corner_angle) - CoreOffset)), 0};
  core_corner_far  = newp;
  Point(core_corner_far) = {far_core_fraction * Sin(far_corner_angle),
    zc + s * (core_offset + far_core_fraction * (Cos(far_corner_angle) - CoreOffset)), 0};
  core_axis_far    = newp;
  Point(core_axis_far) = {0, zc + s * (core_offset - core_size), 0};

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
