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

Include "quarter_ball.geo.inc";

Physical Volume("ball", 1)   = {volumes[]};
Physical Surface("x0", 1)    = {faces_x0[]};
Physical Surface("y0", 2)    = {faces_y0[]};
Physical Surface("sphere", 3) = {faces_sphere[]};
