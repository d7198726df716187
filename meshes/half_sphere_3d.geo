// Half of a solid ball for dyncontact's 3D meshes: the ball of radius R centred at (0, 0, CentreZ),
// cut to y >= 0, for a sphere moving in the x-z plane (an oblique impact on a rigid plane z = 0)
// modelled with the one symmetry plane y = 0. The contact pole is the lowest point
// (0, 0, CentreZ - R). The quarter of meshes/quarter_sphere_3d.geo (whose header documents the
// cubed-sphere layout, the grading toward the pole and the cell shapes) and its mirror in x = 0
// (half_ball.geo.inc, as each ball of oblique_spheres_3d.geo).
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R            sphere radius [length], > 0                                                 (8)
//   CentreZ      z of the centre [length]; the default puts the contact pole at z = 0        (8)
//   N            cells along each inner-cube edge and each shell-block edge parallel to the
//                cube (N per eighth of a great circle), integer >= 1                         (6)
//   NR           cells across each shell block radially (cube face to sphere), integer >= 1  (4)
//   PoleGrading  largest / smallest cell edge along the edges graded toward the contact pole,
//                1 <= PoleGrading <= 10; 1 is uniform                                        (1)
//   TopCap       1: the sphere's top cap (the cube face opposite the pole, latitudes above
//                35 degrees) is physical surface 3, a face to hold or move (a Dirichlet
//                boundary: a ball pressed by a rigid holder); 0: it is part of surface 2     (0)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Volume  1      the body (16 volumes)
//   Physical Surface 1      the symmetry plane y = 0 (a disc)
//   Physical Surface 2      the sphere (half of it; the contact surface), less the top cap if
//                           TopCap = 1
//   Physical Surface 3      with TopCap = 1: the top cap

DefineConstant[
  R = {8, Name "Parameters/R"}, CentreZ = {8, Name "Parameters/CentreZ"},
  N = {6, Name "Parameters/N"}, NR = {4, Name "Parameters/NR"},
  PoleGrading = {1, Name "Parameters/PoleGrading"}, TopCap = {0, Name "Parameters/TopCap"}
];

If (R <= 0)
  Error("half_sphere_3d.geo: R = %g, but the radius must be > 0", R);
EndIf
If (N < 1 || N != Round(N) || NR < 1 || NR != Round(NR))
  Error("half_sphere_3d.geo: N = %g, NR = %g, but both must be integers >= 1", N, NR);
EndIf
If (PoleGrading < 1 || PoleGrading > 10)
  Error("half_sphere_3d.geo: PoleGrading = %g, but it must be in [1, 10]", PoleGrading);
EndIf
If (TopCap != 0 && TopCap != 1)
  Error("half_sphere_3d.geo: TopCap = %g, but it must be 0 or 1", TopCap);
EndIf

Geometry.CopyMeshingMethod = 1;
Include "half_ball.geo.inc";
ball_turn = 0;
ball_centre[] = {0, 0, CentreZ};
Call HalfBall; // sets CentreZ = 0 to build at the origin, then moves the ball to ball_centre[]

// The top cap: the sphere's patches that lie wholly above the centre (the cube face's).
top_cap[] = {};
If (TopCap == 1)
  For k In {0 : #ball_sphere[] - 1}
    box[] = BoundingBox Surface{ball_sphere[k]};
    If (box[2] > CentreZ + 1e-9 * R)
      top_cap[] += {ball_sphere[k]};
    EndIf
  EndFor
  ball_sphere[] -= {top_cap[]};
EndIf

Physical Volume("ball", 1)    = {ball_volumes[]};
Physical Surface("y0", 1)     = {ball_y0[]};
Physical Surface("sphere", 2) = {ball_sphere[]};
If (TopCap == 1)
  Physical Surface("top cap", 3) = {top_cap[]};
EndIf
