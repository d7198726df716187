// Two identical axisymmetric spheres for dyncontact (paper section 6.4), each meshed as
// sphere_graded.geo: unstructured quadrilaterals graded by a gmsh size field toward its contact
// pole, so that the contact zone has square cells of edge PoleSize without refining the whole
// sphere. Radius R, centres on the axis at z = -CentreDistance/2 (body 1, contact pole up) and
// z = +CentreDistance/2 (body 2, contact pole down); the contact plane is z = 0 and, with the
// defaults, the initial gap is 4. The two meshes are generated independently and need not match
// node by node: use Contact/discretization = node-to-segment.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R               sphere radius [length], > 0                                          (8)
//   CentreDistance  distance of the two centres [length], >= 2 R                         (20)
//   PoleSize        cell edge within ZoneRadius of each contact pole [length],
//                   0 < PoleSize <= FarSize                                              (0.1)
//   FarSize         cell edge from distance ZoneRadius + R of the pole on [length],
//                   PoleSize <= FarSize <= R / 8                                         (0.8)
//   ZoneRadius      radius of the zone of uniform cells PoleSize around each contact pole
//                   [length], 0 < ZoneRadius < R                                         (1)
// The size field, the meshing algorithms and the quality figures are those of sphere_graded.geo
// (see its header); the cells of each sphere are those of sphere_graded.geo with the same
// parameters.
//
// Physical groups:
//   Physical Surface 1, 2   body 1, body 2
//   Physical Curve   1      the axis r = 0 (both bodies)
//   Physical Curve   2, 3   the sphere surface of body 1, of body 2

DefineConstant[
  R              = {8,   Name "Parameters/R"},
  CentreDistance = {20,  Name "Parameters/CentreDistance"},
  PoleSize       = {0.1, Name "Parameters/PoleSize"},
  FarSize        = {0.8, Name "Parameters/FarSize"},
  ZoneRadius     = {1,   Name "Parameters/ZoneRadius"}
];

If (R <= 0)
  Error("two_spheres_graded.geo: R = %g, but the radius must be > 0", R);
EndIf
If (CentreDistance < 2 * R - 1e-9 * R)
  Error("two_spheres_graded.geo: CentreDistance = %.17g, but the spheres overlap unless it is >= 2 R = %.17g",
        CentreDistance, 2 * R);
EndIf
If (PoleSize <= 0 || PoleSize > FarSize)
  Error("two_spheres_graded.geo: PoleSize = %g, but it must be in (0, FarSize = %g]", PoleSize,
        FarSize);
EndIf
If (FarSize > R / 8)
  Error("two_spheres_graded.geo: FarSize = %g, but it must be in [PoleSize, R / 8 = %g]", FarSize,
        R / 8);
EndIf
If (ZoneRadius <= 0 || ZoneRadius >= R)
  Error("two_spheres_graded.geo: ZoneRadius = %g, but it must be in (0, R = %g)", ZoneRadius, R);
EndIf

// One graded sphere: centre z = graded_centre_z, contact pole on the side graded_pole_side (+1:
// up), body graded_body (physical surface and curve 1 + graded_body), size field graded_body.
Macro GradedSphere
  s            = graded_pole_side;
  centre       = newp; Point(centre)       = {0, graded_centre_z, 0};
  surface_pole = newp; Point(surface_pole) = {0, graded_centre_z + s * R, 0};
  equator      = newp; Point(equator)      = {R, graded_centre_z, 0};
  surface_far  = newp; Point(surface_far)  = {0, graded_centre_z - s * R, 0};
  // Pole over the equator to the far pole (a gmsh arc spans less than pi), and the axis back.
  arc_pole = newl; Circle(arc_pole) = {surface_pole, centre, equator};
  arc_far  = newl; Circle(arc_far)  = {equator, centre, surface_far};
  axis     = newl; Line(axis)       = {surface_far, surface_pole};
  loop     = newll; Curve Loop(loop) = {arc_pole, arc_far, axis};
  body     = news;  Plane Surface(body) = {loop};
  Recombine Surface {body};

  // The size field of sphere_graded.geo, sizes doubled for the subdivision below.
  Field[2 * graded_body - 1] = Distance;
  Field[2 * graded_body - 1].PointsList = {surface_pole};
  Field[2 * graded_body] = Threshold;
  Field[2 * graded_body].InField = 2 * graded_body - 1;
  Field[2 * graded_body].SizeMin = 2 * PoleSize;
  Field[2 * graded_body].SizeMax = 2 * FarSize;
  Field[2 * graded_body].DistMin = ZoneRadius;
  Field[2 * graded_body].DistMax = ZoneRadius + R;

  Physical Surface(Sprintf("body %g", graded_body), graded_body) = {body};
  Physical Curve(Sprintf("surface of body %g", graded_body), 1 + graded_body) = {arc_pole, arc_far};
  axis_curves[] += {axis};
Return

axis_curves[] = {};
graded_centre_z  = -CentreDistance / 2;
graded_pole_side = 1;
graded_body      = 1;
Call GradedSphere;
graded_centre_z  = CentreDistance / 2;
graded_pole_side = -1;
graded_body      = 2;
Call GradedSphere;
Physical Curve("axis", 1) = {axis_curves[]};

Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;

Mesh.MeshSizeFromPoints         = 0;
Mesh.MeshSizeFromCurvature      = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm                  = 6; // Frontal-Delaunay (see sphere_graded.geo)
Mesh.RecombinationAlgorithm     = 2; // simple full-quad (see sphere_graded.geo)
Mesh.SubdivisionAlgorithm       = 1; // all quadrilaterals
Mesh.Smoothing                  = 5;
