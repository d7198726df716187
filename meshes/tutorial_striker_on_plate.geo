// The striker of doc/tutorial.md: a cylinder with a spherical end (body 1) above a thick plate
// (body 2), for dyncontact, in the (r, z) half plane r >= 0 with gmsh coordinates x = r, y = z.
// The text below this header is, line for line, the .geo that the tutorial has its reader write
// (ctest tutorial.geo_matches_shipped_mesh).
//
// Body 1, the striker: the solid cylinder r <= R, Gap + R <= z <= Gap + R + L on the hemisphere of
// radius R centred on the axis at z = Gap + R, its pole (the contact point) at z = Gap. Body 2,
// the plate: r <= PlateRadius, -PlateThickness <= z <= 0, its top face z = 0 the contact surface.
// The meshes are unstructured and do not match (node-to-segment contact), all quadrilaterals
// (the method of sphere_graded.geo): a Distance field from the two contact points and a Threshold
// field set the cell edge, ContactSize within ZoneRadius of them, growing linearly to FarSize at
// distance ZoneRadius + R; gmsh meshes with twice these sizes (Frontal-Delaunay, the simple
// full-quad recombination) and splits every cell into quadrilaterals, which halves the edges and
// leaves no triangle. Scale multiplies every coordinate of the mesh (gmsh's Mesh.ScalingFactor):
// the geometry is drawn in one unit and meshed in another (Scale = 1e-3: drawn in mm, meshed in
// m), and the mesh is the same, scaled, node for node (gmsh meshes a geometry whose lengths are
// all given 1000 times smaller into other nodes: 1118 of 3182 matched in the tutorial's case, and
// the two runs' forces differed by 3e-5 of the peak, against 3e-13 with Scale).
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters), lengths in the drawing's unit:
//   R               radius of the striker and of its spherical end [length], > 0              (8)
//   L               length of the striker's cylindrical part [length], > 0                    (8)
//   Gap             height of the end's pole above the plate at t = 0 [length], >= 0
//                   (0: touching)                                                          (0.05)
//   PlateRadius     radius of the plate [length], > 0                                        (40)
//   PlateThickness  thickness of the plate [length], > 0                                     (40)
//   ContactSize     cell edge within ZoneRadius of the contact points [length],
//                   0 < ContactSize <= FarSize                                              (0.1)
//   ZoneRadius      radius of the zone of cells of edge ContactSize [length], >= 0          (0.6)
//   FarSize         cell edge from distance ZoneRadius + R of the contact points on [length]  (4)
//   Scale           length of the mesh per unit of the drawing, > 0                           (1)
//
// The defaults: 756 cells (6364 displacement DoFs), shortest edge 0.059, cell edge 0.1 at the
// contact point, about 6 across the Hertz contact radius 0.57 of the tutorial's impact (paper's
// numbers, speed 1). There the peak force is 1.5 % above Hertz's and the contact 1.1 % shorter;
// ContactSize 0.05 (10100 DoFs) gives +1.3 % and -1.1 % (doc/tutorial.md, "What agreement to
// expect, and why").
//
// Physical groups (read by dyncontact as material and boundary ids, see meshes/README.md):
//   Physical Surface 1      the striker (body 1)
//   Physical Surface 2      the plate (body 2)
//   Physical Curve   1      the axis r = 0 (both bodies)
//   Physical Curve   2      the striker's spherical end (a circle about (0, Gap + R): its contact
//                           surface)
//   Physical Curve   3      the plate's top face z = 0 (its contact surface)
//   Physical Curve   4      the plate's side r = PlateRadius
//   Physical Curve   5      the plate's bottom z = -PlateThickness
//   Physical Curve   6      the striker's side r = R
//   Physical Curve   7      the striker's top z = Gap + R + L

// A cylinder of radius R with a spherical end of radius R (body 1) above a thick plate (body 2),
// in the (r, z) half plane r >= 0: gmsh coordinates x = r, y = z.
DefineConstant[
  R              = {8,    Name "Parameters/R"},           // striker radius = end radius
  L              = {8,    Name "Parameters/L"},           // length of the cylindrical part
  Gap            = {0.05, Name "Parameters/Gap"},         // end above the plate at t = 0
  PlateRadius    = {40,   Name "Parameters/PlateRadius"},
  PlateThickness = {40,   Name "Parameters/PlateThickness"},
  ContactSize    = {0.1,  Name "Parameters/ContactSize"},  // cell edge at the contact point,
  ZoneRadius     = {0.6,  Name "Parameters/ZoneRadius"},   // ... within this distance of it
  FarSize        = {4,    Name "Parameters/FarSize"},      // cell edge from ZoneRadius + R on
  Scale          = {1,    Name "Parameters/Scale"}         // the mesh's length per unit above
];
If (R <= 0 || L <= 0 || PlateRadius <= 0 || PlateThickness <= 0 || Scale <= 0 || Gap < 0 ||
    ZoneRadius < 0 || ContactSize <= 0 || ContactSize > FarSize)
  Error("striker_on_plate.geo: a parameter is out of range (meshes/tutorial_striker_on_plate.geo)");
EndIf

// Body 1: the end, a quarter circle about (0, Gap + R) from its pole (0, Gap) to (R, Gap + R);
// the side r = R up to the top z = Gap + R + L; the axis back.
pole   = newp; Point(pole)   = {0, Gap, 0};
centre = newp; Point(centre) = {0, Gap + R, 0};
rim    = newp; Point(rim)    = {R, Gap + R, 0};
corner = newp; Point(corner) = {R, Gap + R + L, 0};
top    = newp; Point(top)    = {0, Gap + R + L, 0};
end_arc      = newl; Circle(end_arc)    = {pole, centre, rim};
striker_side = newl; Line(striker_side) = {rim, corner};
striker_top  = newl; Line(striker_top)  = {corner, top};
striker_axis = newl; Line(striker_axis) = {top, pole};
Curve Loop(1) = {end_arc, striker_side, striker_top, striker_axis};
Plane Surface(1) = {1};

// Body 2: the plate, r <= PlateRadius, -PlateThickness <= z <= 0.
origin     = newp; Point(origin)     = {0, 0, 0};
plate_rim  = newp; Point(plate_rim)  = {PlateRadius, 0, 0};
plate_edge = newp; Point(plate_edge) = {PlateRadius, -PlateThickness, 0};
plate_foot = newp; Point(plate_foot) = {0, -PlateThickness, 0};
plate_top  = newl; Line(plate_top)  = {origin, plate_rim};
plate_side = newl; Line(plate_side) = {plate_rim, plate_edge};
plate_base = newl; Line(plate_base) = {plate_edge, plate_foot};
plate_axis = newl; Line(plate_axis) = {plate_foot, origin};
Curve Loop(2) = {plate_top, plate_side, plate_base, plate_axis};
Plane Surface(2) = {2};

// Cells of edge ContactSize within ZoneRadius of the contact point, growing linearly to FarSize
// at distance ZoneRadius + R. gmsh meshes with twice these sizes, recombines the triangles into
// quadrilaterals and splits every cell into quadrilaterals (none is left a triangle).
Field[1] = Distance; Field[1].PointsList = {pole, origin};
Field[2] = Threshold; Field[2].InField = 1;
Field[2].DistMin = ZoneRadius;       Field[2].DistMax = ZoneRadius + R;
Field[2].SizeMin = 2 * ContactSize;  Field[2].SizeMax = 2 * FarSize;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0; Mesh.MeshSizeFromCurvature = 0; Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;               // Frontal-Delaunay
Mesh.RecombinationAlgorithm = 2;  // simple full-quad
Mesh.SubdivisionAlgorithm = 1;    // all quadrilaterals
Recombine Surface {1, 2};
Mesh.ScalingFactor = Scale;       // e.g. 1e-3: drawn in mm, meshed in m

// Physical surface b = body b; physical curve 1 = the axis; every other physical curve is one
// boundary of one body, a circle centred on the axis or a straight line.
Physical Surface("striker", 1)    = {1};
Physical Surface("plate", 2)      = {2};
Physical Curve("axis", 1)         = {striker_axis, plate_axis};
Physical Curve("striker end", 2)  = {end_arc};
Physical Curve("plate top", 3)    = {plate_top};
Physical Curve("plate side", 4)   = {plate_side};
Physical Curve("plate bottom", 5) = {plate_base};
Physical Curve("striker side", 6) = {striker_side};
Physical Curve("striker top", 7)  = {striker_top};
