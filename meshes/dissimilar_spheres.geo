// Two axisymmetric spheres of different radii for dyncontact: body 1 of radius R1 below, body 2 of
// radius R2 above, centres on the axis, the contact poles Gap apart and symmetric about z = 0:
// body 1's centre at z = -Gap/2 - R1 (contact pole at z = -Gap/2), body 2's at z = Gap/2 + R2
// (contact pole at z = +Gap/2). Both are built by the macro of sphere.geo with the same
// resolution parameters, so each has 4 * Divisions * 2^Refinement surface edges growing by
// PoleGrading from its contact pole to its far pole: the edges of body 2 are R2/R1 times those of
// body 1 at the same angle, and the facing surface nodes do not match (same angles on different
// radii: equal r only at the contact poles, on the axis).
//
// The contact zone is resolved by the grading along the surface (and SurfaceGrading across it),
// not by refining the whole spheres: at the defaults the edge at the contact pole is about 1/3 of
// the edge at the far pole.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R1   radius of body 1 (below) [length], > 0                                            (8)
//   R2   radius of body 2 (above) [length], > 0                                            (4)
//   Gap  initial gap between the contact poles [length], >= 0 (0: the spheres touch)        (4)
//   and Divisions, RadialDivisions, Refinement, PoleGrading, SurfaceGrading, CoreOffset as in
//   sphere.geo, for both spheres.
//
// Resolution at the contact poles (cells of body 1 + body 2; chord of the surface element edge at
// the contact pole of body 1, of body 2; the rest of each sphere grows to PoleGrading times that):
//   defaults (PoleGrading 3)                              216 + 216 cells, edges 0.57, 0.29
//   PoleGrading 10, CoreOffset 0.3                        216 + 216 cells, edges 0.26, 0.13
// Each Refinement level quadruples the cells and halves the edges.
//
// Physical groups:
//   Physical Surface 1, 2   body 1 (radius R1), body 2 (radius R2)
//   Physical Curve   1      the axis r = 0 (both bodies)
//   Physical Curve   2, 3   the sphere surface of body 1, of body 2

SphereMacroOnly = 1;
Include "sphere.geo";

DefineConstant[
  R1  = {8, Name "Parameters/R1"},
  R2  = {4, Name "Parameters/R2"},
  Gap = {4, Name "Parameters/Gap"}
];
If (R1 <= 0)
  Error("dissimilar_spheres.geo: R1 = %g, but the radius must be > 0", R1);
EndIf
If (R2 <= 0)
  Error("dissimilar_spheres.geo: R2 = %g, but the radius must be > 0", R2);
EndIf
If (Gap < 0)
  Error("dissimilar_spheres.geo: Gap = %g, but the spheres overlap unless it is >= 0", Gap);
EndIf

sphere_divisions = Divisions;

sphere_radius    = R1;
sphere_centre_z  = -Gap / 2 - R1;
sphere_pole_side = 1;
sphere_body      = 1;
Call SphereBody;

sphere_radius    = R2;
sphere_centre_z  = Gap / 2 + R2;
sphere_pole_side = -1;
sphere_body      = 2;
Call SphereBody;

Physical Curve("axis", 1) = {axis_curves[]};
