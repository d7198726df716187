// Three axisymmetric spheres of radius R on the axis for dyncontact, a test of several bodies and
// contact pairs (prm/three_spheres.prm): body 1 centred at z = -CentreDistance with its contact pole
// on top, body 2 at z = 0, body 3 at z = +CentreDistance with its contact pole below (the mirror
// image of body 1). Built by the macro of sphere.geo; with PoleGrading 1 and CoreOffset 0 body 2
// is symmetric about z = 0 too, and the whole mesh is the mirror image of itself.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R               sphere radius [length], > 0                                            (4)
//   CentreDistance  distance of neighbouring centres [length], >= 2 R                     (10)
//   and Divisions, RadialDivisions, Refinement, PoleGrading, SurfaceGrading, CoreOffset as in
//   sphere.geo, for all three spheres.
//
// Physical groups:
//   Physical Surface 1, 2, 3   body 1, 2, 3
//   Physical Curve   1         the axis r = 0 (all bodies)
//   Physical Curve   2, 3, 4   the sphere surface of body 1, 2, 3

SphereMacroOnly = 1;
Include "sphere.geo";

DefineConstant[
  R              = {4, Name "Parameters/R"},
  CentreDistance = {10, Name "Parameters/CentreDistance"}
];
If (R <= 0)
  Error("three_spheres.geo: R = %g, but the radius must be > 0", R);
EndIf
If (CentreDistance < 2 * R)
  Error("three_spheres.geo: CentreDistance = %g, but the spheres overlap unless it is >= 2 R = %g",
        CentreDistance, 2 * R);
EndIf

sphere_divisions = Divisions;
sphere_radius    = R;

sphere_centre_z  = -CentreDistance;
sphere_pole_side = 1;
sphere_body      = 1;
Call SphereBody;

sphere_centre_z  = 0;
sphere_pole_side = 1;
sphere_body      = 2;
Call SphereBody;

sphere_centre_z  = CentreDistance;
sphere_pole_side = -1;
sphere_body      = 3;
Call SphereBody;

Physical Curve("axis", 1) = {axis_curves[]};
