// Hertz line contact for dyncontact (Problem/geometry = plane strain mesh): a long cylinder of
// radius R lying on a block, as the half model x >= 0 of the cross-section in the (x, y) plane,
// both bodies cut by the symmetry plane x = 0. Body 1, the cylinder: the half disc x >= 0 of
// radius R centred at (0, Gap + R), its lowest point (0, Gap) the contact point. Body 2, the
// block: [0, Width] x [-Height, 0], its top face y = 0 the contact surface, the contact point at
// the origin. With Gap = 0 the bodies touch at the origin (two distinct vertices there: the
// bodies share no node).
//
// The meshes are unstructured and do not match (mortar contact), all quadrilaterals, by the
// method of sphere_graded.geo and tutorial_striker_on_plate.geo (contact_zone_sizes.geo.inc):
// h = ContactSize in the cylinder and BlockSizeRatio * ContactSize in the block within ZoneRadius
// of the contact point, growing linearly to FarSize at distance ZoneRadius + R and FarSize
// beyond. gmsh meshes with twice these sizes (Frontal-Delaunay triangles, recombined by the simple
// full-quad algorithm) and splits every cell into quadrilaterals (Mesh.SubdivisionAlgorithm = 1),
// which halves the edges and leaves no triangle; the vertices the split adds on the arc are placed on
// the circle (dyncontact fits a circle to them, tolerance 1e-6 R). The default BlockSizeRatio
// 1.25 makes the block's top face edges longer than the cylinder's at the contact (the slave
// side, the cylinder's arc, the finer one, as mortar contact is usually set up), so that
// no node of one surface faces a node of the other but by chance.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R               radius of the cylinder [length], > 0                                   (10)
//   Gap             height of the cylinder's lowest point above the block at t = 0
//                   [length], >= 0 (0: touching at the origin)                               (0)
//   Width           extent of the block in x from the symmetry plane [length], > ZoneRadius (10)
//   Height          depth of the block [length], > ZoneRadius                               (10)
//   ContactSize     cell edge of the cylinder within ZoneRadius of the contact point
//                   [length], 0 < ContactSize <= FarSize                                   (0.05)
//   BlockSizeRatio  the block's cell edge there / ContactSize, > 0 (< 1: the block finer,
//                   > 1: coarser), BlockSizeRatio * ContactSize <= FarSize; != 1 keeps the
//                   two contact surfaces' nodes apart                                      (1.25)
//   ZoneRadius      radius of the zone of the finest cells about the contact point
//                   [length], 0 < ZoneRadius < R                                             (2)
//   FarSize         cell edge from distance ZoneRadius + R of the contact point on
//                   [length], <= R / 4                                                       (2)
//
// The defaults suit prm/cylinder_on_block_plane_strain.prm (E = 1000, nu = 0.3, the weight of the
// cylinder under gravity 0.1: Hertz's contact half-width a = 0.853): ZoneRadius = 2.3 a, about
// 17 cylinder edges and 15 block edges across the half-width. Measured (gmsh 4.8.4; gmsh rounds
// the number of edges on each curve up): cells of cylinder + block, the edges along the two
// contact surfaces within the zone (cylinder's arc, block's top face), the corner angles:
//   defaults                              2216 + 1656 cells, edges 0.0491, 0.0562, 43.8 - 139.4 deg
//   BlockSizeRatio 0.8                    2216 + 3376 cells, edges 0.0491, 0.0394, 38.6 - 144.5 deg
//   ContactSize 0.1, BlockSizeRatio 1      888 +  924 cells
// and the arc's vertices on the circle to 2e-16 R.
//
// Physical groups (read by dyncontact as material and boundary ids, see meshes/README.md; in
// plane strain every physical curve is a boundary curve of one body, each a separate id):
//   Physical Surface 1      the cylinder (body 1)
//   Physical Surface 2      the block (body 2)
//   Physical Curve   1      the cylinder's symmetry line x = 0 (a symmetry plane)
//   Physical Curve   2      the cylinder's lower quarter arc, from (0, Gap) to (R, Gap + R): its
//                           contact surface (a circle about (0, Gap + R))
//   Physical Curve   3      the block's top face y = 0 (its contact surface)
//   Physical Curve   4      the block's symmetry line x = 0 (a symmetry plane)
//   Physical Curve   5      the block's bottom y = -Height (to clamp)
//   Physical Curve   6      the block's side x = Width (free)
//   Physical Curve   7      the cylinder's upper quarter arc, from (R, Gap + R) to (0, Gap + 2 R)
//                           (free)

DefineConstant[
  R              = {10,   Name "Parameters/R"},
  Gap            = {0,    Name "Parameters/Gap"},
  Width          = {10,   Name "Parameters/Width"},
  Height         = {10,   Name "Parameters/Height"},
  ContactSize    = {0.05, Name "Parameters/ContactSize"},
  BlockSizeRatio = {1.25, Name "Parameters/BlockSizeRatio"},
  ZoneRadius     = {2,    Name "Parameters/ZoneRadius"},
  FarSize        = {2,    Name "Parameters/FarSize"}
];

If (R <= 0)
  Error("cylinder_on_block.geo: R = %g, but the radius must be > 0", R);
EndIf
If (Gap < 0)
  Error("cylinder_on_block.geo: Gap = %g, but the bodies overlap unless it is >= 0", Gap);
EndIf
If (ZoneRadius <= 0 || ZoneRadius >= R)
  Error("cylinder_on_block.geo: ZoneRadius = %g, but it must be in (0, R = %g)", ZoneRadius, R);
EndIf
If (Width <= ZoneRadius || Height <= ZoneRadius)
  Error("cylinder_on_block.geo: Width = %g, Height = %g, but both must be > ZoneRadius = %g",
        Width, Height, ZoneRadius);
EndIf
If (FarSize > R / 4)
  Error("cylinder_on_block.geo: FarSize = %g, but it must be <= R / 4 = %g", FarSize, R / 4);
EndIf
If (ContactSize <= 0 || ContactSize > FarSize)
  Error("cylinder_on_block.geo: ContactSize = %g, but it must be in (0, FarSize = %g]",
        ContactSize, FarSize);
EndIf
If (BlockSizeRatio <= 0 || BlockSizeRatio * ContactSize > FarSize)
  Error("cylinder_on_block.geo: BlockSizeRatio = %g, but it must be in (0, FarSize / ContactSize]",
        BlockSizeRatio);
EndIf

// Body 1: the half disc, its boundary the lower quarter arc from the contact point to the
// equator, the upper quarter arc to the top (a gmsh circle arc spans less than pi) and the
// symmetry line back down.
pole    = newp; Point(pole)    = {0, Gap, 0};
centre  = newp; Point(centre)  = {0, Gap + R, 0};
equator = newp; Point(equator) = {R, Gap + R, 0};
summit  = newp; Point(summit)  = {0, Gap + 2 * R, 0};
lower_arc     = newl; Circle(lower_arc) = {pole, centre, equator};
upper_arc     = newl; Circle(upper_arc) = {equator, centre, summit};
cylinder_axis = newl; Line(cylinder_axis) = {summit, pole};
cylinder_loop = newll; Curve Loop(cylinder_loop) = {lower_arc, upper_arc, cylinder_axis};
cylinder = news; Plane Surface(cylinder) = {cylinder_loop};

// Body 2: the block, counter-clockwise from the contact point at the origin.
origin       = newp; Point(origin)       = {0, 0, 0};
top_corner   = newp; Point(top_corner)   = {Width, 0, 0};
foot_corner  = newp; Point(foot_corner)  = {Width, -Height, 0};
foot         = newp; Point(foot)         = {0, -Height, 0};
block_bottom = newl; Line(block_bottom) = {foot, foot_corner};
block_side   = newl; Line(block_side)   = {foot_corner, top_corner};
block_top    = newl; Line(block_top)    = {top_corner, origin};
block_axis   = newl; Line(block_axis)   = {origin, foot};
block_loop = newll; Curve Loop(block_loop) = {block_bottom, block_side, block_top, block_axis};
block = news; Plane Surface(block) = {block_loop};

contact_points[]  = {pole, origin};
cylinder_curves[] = {lower_arc, upper_arc, cylinder_axis};
cylinder_points[] = {pole, equator, summit};
block_curves[]    = {block_bottom, block_side, block_top, block_axis};
block_points[]    = {origin, top_corner, foot_corner, foot};
Include "contact_zone_sizes.geo.inc";

// Physical surface b = body b; every physical curve is one boundary of one body, a circle or a
// straight line.
Physical Surface("cylinder", 1)              = {cylinder};
Physical Surface("block", 2)                 = {block};
Physical Curve("cylinder symmetry line", 1)  = {cylinder_axis};
Physical Curve("cylinder contact arc", 2)    = {lower_arc};
Physical Curve("block top", 3)               = {block_top};
Physical Curve("block symmetry line", 4)     = {block_axis};
Physical Curve("block bottom", 5)            = {block_bottom};
Physical Curve("block side", 6)              = {block_side};
Physical Curve("cylinder upper arc", 7)      = {upper_arc};
