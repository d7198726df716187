// Axisymmetric sphere for dyncontact, graded toward its contact pole by a gmsh size field: the
// half disc r >= 0 of radius R in the (r, z) plane, gmsh coordinates x = r, y = z, meshed
// unstructured into quadrilaterals only. Made for contact studies whose contact radius is a small
// fraction of R (the Hertz limit, bench/hertz_limit.sh), where the transfinite O-grid of
// sphere.geo would need many refinement levels of the whole body to put enough elements across
// the contact.
//
// The contact pole is the point of the surface on the axis that faces the other body:
// z = CentreZ + PoleSide * R. The element edge h is set by the distance d from the contact pole
// (a Distance field and a Threshold field): h = PoleSize for d <= ZoneRadius, growing linearly in
// d to FarSize at d = ZoneRadius + R, and FarSize beyond (the far side of the sphere). PoleSize
// and FarSize are the edges of the final quadrilateral cells (the Q2 element edges): gmsh meshes
// with twice these sizes (Frontal-Delaunay triangles, recombined by the simple full-quad
// algorithm) and then splits every cell into quadrilaterals (Mesh.SubdivisionAlgorithm = 1),
// which halves the edges and leaves no triangle. The vertices that the split adds on the surface
// are placed on the circle, so every surface vertex lies on it to round-off (dyncontact fits a
// circle to them, tolerance 1e-6 R).
// Along the surface the edges near the contact pole come out 0.87-0.99 PoleSize (measured below).
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R           sphere radius [length], > 0                                               (8)
//   CentreZ     z of the centre [length]                                                  (0)
//   PoleSide    +1: contact pole at z = CentreZ + R (body 1 of dyncontact), -1: at
//               z = CentreZ - R (the mirror image)                                        (1)
//   PoleSize    cell edge within ZoneRadius of the contact pole [length],
//               0 < PoleSize <= FarSize                                                   (0.05)
//   FarSize     cell edge from distance ZoneRadius + R of the pole on [length],
//               PoleSize <= FarSize <= R / 8                                              (0.8)
//   ZoneRadius  radius of the zone of uniform cells PoleSize around the contact pole
//               [length], 0 < ZoneRadius < R                                              (0.5)
//
// Measured (R = 8, FarSize 0.8; gmsh 4.8.4): cells; the chord of the surface edges near the
// contact pole (gmsh rounds the number of edges on each arc up, so they come out 0.87-0.99
// PoleSize); the smallest and largest corner angle over all cells (of the straight-sided cells on
// the vertices; no cell is inverted or degenerate). The settings of bench/hertz_limit.sh are
// PoleSize = a_max / 8 (level 0) or a_max / 16 (level 1) and ZoneRadius = 2 a_max, a_max the Hertz
// contact radius at the density rho:
//   PoleSize   ZoneRadius   cells   pole edge   angles [deg]   setting
//   0.05       0.5            920   0.0468      45 - 134       the defaults
//   0.0935     1.496         1112   0.0868      47 - 136       rho = 1e-2, level 0
//   0.0468     1.496         2168   0.0432      39 - 139       rho = 1e-2, level 1
//   0.0590     0.944         1240   0.0516      40 - 136       rho = 1e-3, level 0
//   0.0295     0.944         2480   0.0292      41 - 137       rho = 1e-3, level 1
//   0.0235     0.376         1460   0.0212      46 - 138       rho = 1e-5, level 0
//   0.0148     0.237         1480   0.0144      42 - 143       rho = 1e-6, level 0
//   0.00935    0.150         1572   0.0087      45 - 137       rho = 1e-7, level 0
//   0.00468    0.150         2984   0.0044      35 - 140       rho = 1e-7, level 1
//   0.0125     2.0          27968   0.0124      43 - 135       a wide zone: cells ~ (ZoneRadius /
//                                                              PoleSize)^2
// Over PoleSize 0.003-0.1 x ZoneRadius 0.1-2 (54 settings) every angle lay in 32-146 degrees and
// every surface vertex on the circle to 2e-16 R. gmsh's Blossom recombination (1) instead of the
// simple full-quad one (2) left cells with a 174 degree corner on the coarse far surface, and so
// did FarSize 1; the quadrilateral variant of Frontal-Delaunay (Mesh.Algorithm 8) crashes in gmsh
// 4.8.4 with a background size field.
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Surface 1      the body
//   Physical Curve   1      the axis r = 0
//   Physical Curve   2      the sphere surface

DefineConstant[
  R          = {8,    Name "Parameters/R"},
  CentreZ    = {0,    Name "Parameters/CentreZ"},
  PoleSide   = {1,    Name "Parameters/PoleSide"},
  PoleSize   = {0.05, Name "Parameters/PoleSize"},
  FarSize    = {0.8,  Name "Parameters/FarSize"},
  ZoneRadius = {0.5,  Name "Parameters/ZoneRadius"}
];

If (R <= 0)
  Error("sphere_graded.geo: R = %g, but the radius must be > 0", R);
EndIf
If (PoleSide != 1 && PoleSide != -1)
  Error("sphere_graded.geo: PoleSide = %g, but only +1 and -1 are allowed", PoleSide);
EndIf
If (PoleSize <= 0 || PoleSize > FarSize)
  Error("sphere_graded.geo: PoleSize = %g, but it must be in (0, FarSize = %g]", PoleSize,
        FarSize);
EndIf
If (FarSize > R / 8)
  Error("sphere_graded.geo: FarSize = %g, but it must be in [PoleSize, R / 8 = %g]", FarSize,
        R / 8);
EndIf
If (ZoneRadius <= 0 || ZoneRadius >= R)
  Error("sphere_graded.geo: ZoneRadius = %g, but it must be in (0, R = %g)", ZoneRadius, R);
EndIf

s = PoleSide;

centre       = newp; Point(centre)       = {0, CentreZ, 0};
surface_pole = newp; Point(surface_pole) = {0, CentreZ + s * R, 0};
equator      = newp; Point(equator)      = {R, CentreZ, 0};
surface_far  = newp; Point(surface_far)  = {0, CentreZ - s * R, 0};

// The surface from the contact pole over the equator to the far pole (two arcs: a gmsh circle
// arc spans less than pi), and the axis back.
arc_pole = newl; Circle(arc_pole) = {surface_pole, centre, equator};
arc_far  = newl; Circle(arc_far)  = {equator, centre, surface_far};
axis     = newl; Line(axis)       = {surface_far, surface_pole};

loop = newll; Curve Loop(loop) = {arc_pole, arc_far, axis};
body = news;  Plane Surface(body) = {loop};

// The size field, with the sizes doubled for the subdivision below.
Field[1] = Distance;
Field[1].PointsList = {surface_pole};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = 2 * PoleSize;
Field[2].SizeMax = 2 * FarSize;
Field[2].DistMin = ZoneRadius;
Field[2].DistMax = ZoneRadius + R;
Background Field = 2;

Mesh.MeshSizeFromPoints       = 0;
Mesh.MeshSizeFromCurvature    = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm                = 6; // Frontal-Delaunay (see the header)
Mesh.RecombinationAlgorithm   = 2; // simple full-quad (see the header)
Mesh.SubdivisionAlgorithm     = 1; // all quadrilaterals
Mesh.Smoothing                = 5;
Recombine Surface {body};

Physical Surface("body 1", 1)            = {body};
Physical Curve("axis", 1)                = {axis};
Physical Curve("surface of body 1", 2)   = {arc_pole, arc_far};
