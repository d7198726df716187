// Two solid balls for dyncontact's 3D oblique impact (prm/oblique_spheres_3d.prm): ball 1 of radius
// R1 and ball 2 of radius R2, their line of centres in the plane y = 0 at the angle Angle from the
// z axis, so that ball 2 moving along -z strikes ball 1 obliquely. Both are cut to y >= 0 (the
// plane of the line of centres and of the impact direction z is a symmetry plane of the problem):
// two half balls on the symmetry plane y = 0. With d = (sin Angle, 0, cos Angle), ball 1 is centred
// at -(R1 + Gap / 2) d and ball 2 at (R2 + Gap / 2) d: they face each other across Gap along the
// line of centres, about the origin.
// Each half ball is two quarter balls of meshes/quarter_ball.geo.inc (the cubed sphere of
// quarter_sphere_3d.geo, whose header documents the layout, grading and cell shapes), the second
// the mirror image of the first in x = 0, merged into one conforming mesh; its pole, toward which
// PoleGrading refines the cells, is then turned about y to point at the other ball along the line
// of centres. With N1 != N2 (or NR1 != NR2) the two balls' meshes do not match: node-to-surface
// contact. Structured hexahedra only.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R1, R2       the balls' radii [length], > 0                                            (8, 8)
//   Angle        between the z axis and the line of centres [degrees], 0 <= Angle <= 80;
//                0 is the central impact on the same meshes                                 (30)
//   Gap          between the balls along the line of centres [length], > 0                (0.01)
//   N1, N2       cells along each inner-cube edge and each shell-block edge parallel to the
//                cube, per ball (N per eighth of a great circle), integers >= 1             (6, 5)
//   NR1, NR2     cells across each shell block radially, per ball, integers >= 1           (4, 4)
//   PoleGrading  largest / smallest cell edge along the edges graded toward each ball's pole,
//                1 <= PoleGrading <= 10; 1 is uniform                                         (1)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Volume  1, 2   ball 1, ball 2
//   Physical Surface 1      ball 1's face on the symmetry plane y = 0 (a disc)
//   Physical Surface 2      ball 1's sphere (a half sphere; a contact surface)
//   Physical Surface 3      ball 2's face on the symmetry plane y = 0
//   Physical Surface 4      ball 2's sphere

DefineConstant[
  R1 = {8, Name "Parameters/R1"}, R2 = {8, Name "Parameters/R2"},
  Angle = {30, Name "Parameters/Angle"}, Gap = {0.01, Name "Parameters/Gap"},
  N1 = {6, Name "Parameters/N1"}, N2 = {5, Name "Parameters/N2"},
  NR1 = {4, Name "Parameters/NR1"}, NR2 = {4, Name "Parameters/NR2"},
  PoleGrading = {1, Name "Parameters/PoleGrading"}
];

If (R1 <= 0 || R2 <= 0)
  Error("oblique_spheres_3d.geo: R1 = %g, R2 = %g, but both radii must be > 0", R1, R2);
EndIf
If (Angle < 0 || Angle > 80)
  Error("oblique_spheres_3d.geo: Angle = %g, but it must be in [0, 80] degrees", Angle);
EndIf
If (Gap <= 0)
  Error("oblique_spheres_3d.geo: Gap = %g, but it must be > 0", Gap);
EndIf
If (N1 < 1 || N1 != Round(N1) || NR1 < 1 || NR1 != Round(NR1) ||
    N2 < 1 || N2 != Round(N2) || NR2 < 1 || NR2 != Round(NR2))
  Error("oblique_spheres_3d.geo: N1 = %g, NR1 = %g, N2 = %g, NR2 = %g, but all must be integers >= 1",
        N1, NR1, N2, NR2);
EndIf
If (PoleGrading < 1 || PoleGrading > 10)
  Error("oblique_spheres_3d.geo: PoleGrading = %g, but it must be in [1, 10]", PoleGrading);
EndIf

// The mirrored quarter balls keep their transfinite layout.
Geometry.CopyMeshingMethod = 1;
theta = Angle * Pi / 180;

Include "half_ball.geo.inc";

// Ball 1: pole turned from -z to +d (a half turn, then Angle), centre -(R1 + Gap / 2) d.
R = R1; N = N1; NR = NR1;
ball_turn = Pi + theta;
ball_centre[] = {-(R1 + Gap / 2) * Sin(theta), 0, -(R1 + Gap / 2) * Cos(theta)};
Call HalfBall;
Physical Volume("ball 1", 1) = {ball_volumes[]};
Physical Surface("ball 1 y0", 1) = {ball_y0[]};
Physical Surface("ball 1 sphere", 2) = {ball_sphere[]};

// Ball 2: pole turned from -z to -d (Angle), centre (R2 + Gap / 2) d.
R = R2; N = N2; NR = NR2;
ball_turn = theta;
ball_centre[] = {(R2 + Gap / 2) * Sin(theta), 0, (R2 + Gap / 2) * Cos(theta)};
Call HalfBall;
Physical Volume("ball 2", 2) = {ball_volumes[]};
Physical Surface("ball 2 y0", 3) = {ball_y0[]};
Physical Surface("ball 2 sphere", 4) = {ball_sphere[]};
