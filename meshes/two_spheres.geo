// Two identical axisymmetric spheres for dyncontact (paper section 6.4): radius R, centres on the
// axis at z = -CentreDistance/2 (body 1) and z = +CentreDistance/2 (body 2), so the contact plane
// is z = 0 and, with the defaults R = 8 and CentreDistance = 20, the initial gap is 4. Body 1 is
// the lower sphere with its contact pole at z = CentreDistance/2 - R; body 2 is its mirror image
// about z = 0. Both are built by the macro of sphere.geo from the same transfinite data, with the
// axial coordinate negated, so their meshes mirror each other node by node, including the facing
// (contact) surfaces.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   CentreDistance  distance of the two centres [length], >= 2 R (the spheres may touch but not
//                   overlap)                                                             (20)
//   and R, Divisions, RadialDivisions, Refinement, PoleGrading, SurfaceGrading, CoreOffset as in
//   sphere.geo (CentreZ and PoleSide are set here and are not parameters of this file).
//
// The graded family for the Hertz impact (see sphere.geo; cells for both bodies, smallest surface
// edge at the contact poles):
//   coarse  Refinement 0, PoleGrading 10, CoreOffset 0.3     432 cells, edge 0.26
//   medium  Refinement 1, PoleGrading 10, CoreOffset 0.3    1728 cells, edge 0.13
//   fine    Refinement 2, PoleGrading 10, CoreOffset 0.3    6912 cells, edge 0.067
//
// Physical groups:
//   Physical Surface 1, 2   body 1, body 2
//   Physical Curve   1      the axis r = 0 (both bodies)
//   Physical Curve   2, 3   the sphere surface of body 1, of body 2

SphereMacroOnly = 1;
Include "sphere.geo";

DefineConstant[ CentreDistance = {20, Name "Parameters/CentreDistance"} ];
// Touching (to 1e-9 R, round-off of typed numbers) is allowed: the contact poles then coincide.
If (CentreDistance < 2 * R - 1e-9 * R)
  Error("two_spheres.geo: CentreDistance = %.17g, but the spheres overlap unless it is >= 2 R = %.17g",
        CentreDistance, 2 * R);
EndIf

sphere_centre_z  = -CentreDistance / 2;
sphere_pole_side = 1;
sphere_body      = 1;
Call SphereBody;

sphere_centre_z  = CentreDistance / 2;
sphere_pole_side = -1;
sphere_body      = 2;
Call SphereBody;

Physical Curve("axis", 1) = {axis_curves[]};
