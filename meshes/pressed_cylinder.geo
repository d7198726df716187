// A cylinder pressed on a block for dyncontact (Problem/geometry = plane strain mesh), the whole
// cross-section in the (x, y) plane, for loads that are not symmetric (Cattaneo-Mindlin: a
// tangential load after the normal one). Body 1, the cylinder: the lower half disc of radius R
// centred at (0, Gap + R), its lowest point (0, Gap) the contact point, its flat top y = Gap + R
// (through the centre) the face a Dirichlet boundary moves. Body 2, the block:
// [-Width, Width] x [-Height, 0], its top face y = 0 the contact surface. With Gap = 0 the bodies
// touch at the origin (two distinct vertices there: the bodies share no node).
//
// The cells are unstructured quadrilaterals sized as in cylinder_on_block.geo (its half model;
// contact_zone_sizes.geo.inc): ContactSize in the cylinder and BlockSizeRatio * ContactSize in the
// block within ZoneRadius of the contact point, growing linearly to FarSize at distance
// ZoneRadius + R. The vertices the subdivision adds on the arc are placed on the circle.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R               radius of the cylinder [length], > 0                                   (10)
//   Gap             height of the cylinder's lowest point above the block at t = 0
//                   [length], >= 0 (0: touching at the origin)                               (0)
//   Width           half the extent of the block in x [length], > ZoneRadius               (10)
//   Height          depth of the block [length], > ZoneRadius                               (10)
//   ContactSize     cell edge of the cylinder within ZoneRadius of the contact point
//                   [length], 0 < ContactSize <= FarSize                                   (0.1)
//   BlockSizeRatio  the block's cell edge there / ContactSize, > 0, BlockSizeRatio *
//                   ContactSize <= FarSize; != 1 keeps the two surfaces' nodes apart       (1.25)
//   ZoneRadius      radius of the zone of the finest cells about the contact point
//                   [length], 0 < ZoneRadius < R                                             (2)
//   FarSize         cell edge from distance ZoneRadius + R of the contact point on
//                   [length], <= R / 4                                                       (2)
//
// Measured (gmsh 4.8.4), cells of cylinder + block: defaults 1504 + 1200 (22,020 DoFs);
// ContactSize 0.05: 4248 + 3308 (see prm/cattaneo_cylinders.prm).
//
// Physical groups (read by dyncontact as material and boundary ids, see meshes/README.md):
//   Physical Surface 1      the cylinder (body 1)
//   Physical Surface 2      the block (body 2)
//   Physical Curve   1      the cylinder's flat top y = Gap + R (to load)
//   Physical Curve   2      the cylinder's arc, from (-R, Gap + R) through (0, Gap) to
//                           (R, Gap + R): its contact surface (a circle about (0, Gap + R))
//   Physical Curve   3      the block's top face y = 0 (its contact surface)
//   Physical Curve   4      the block's bottom y = -Height (to clamp)
//   Physical Curve   5, 6   the block's sides x = -Width and x = Width (free)

DefineConstant[
  R              = {10,   Name "Parameters/R"},
  Gap            = {0,    Name "Parameters/Gap"},
  Width          = {10,   Name "Parameters/Width"},
  Height         = {10,   Name "Parameters/Height"},
  ContactSize    = {0.1,  Name "Parameters/ContactSize"},
  BlockSizeRatio = {1.25, Name "Parameters/BlockSizeRatio"},
  ZoneRadius     = {2,    Name "Parameters/ZoneRadius"},
  FarSize        = {2,    Name "Parameters/FarSize"}
];

If (R <= 0)
  Error("pressed_cylinder.geo: R = %g, but the radius must be > 0", R);
EndIf
If (Gap < 0)
  Error("pressed_cylinder.geo: Gap = %g, but the bodies overlap unless it is >= 0", Gap);
EndIf
If (ZoneRadius <= 0 || ZoneRadius >= R)
  Error("pressed_cylinder.geo: ZoneRadius = %g, but it must be in (0, R = %g)", ZoneRadius, R);
EndIf
If (Width <= ZoneRadius || Height <= ZoneRadius)
  Error("pressed_cylinder.geo: Width = %g, Height = %g, but both must be > ZoneRadius = %g",
        Width, Height, ZoneRadius);
EndIf
If (FarSize > R / 4)
  Error("pressed_cylinder.geo: FarSize = %g, but it must be <= R / 4 = %g", FarSize, R / 4);
EndIf
If (ContactSize <= 0 || ContactSize > FarSize)
  Error("pressed_cylinder.geo: ContactSize = %g, but it must be in (0, FarSize = %g]",
        ContactSize, FarSize);
EndIf
If (BlockSizeRatio <= 0 || BlockSizeRatio * ContactSize > FarSize)
  Error("pressed_cylinder.geo: BlockSizeRatio = %g, but it must be in (0, FarSize / ContactSize]",
        BlockSizeRatio);
EndIf

// Body 1: the lower half disc, counter-clockwise from its left end: two quarter arcs through the
// contact point (a gmsh circle arc spans less than pi), then the flat top back.
left   = newp; Point(left)   = {-R, Gap + R, 0};
pole   = newp; Point(pole)   = {0, Gap, 0};
right  = newp; Point(right)  = {R, Gap + R, 0};
centre = newp; Point(centre) = {0, Gap + R, 0};
left_arc  = newl; Circle(left_arc)  = {left, centre, pole};
right_arc = newl; Circle(right_arc) = {pole, centre, right};
flat_top  = newl; Line(flat_top)    = {right, left};
cylinder_loop = newll; Curve Loop(cylinder_loop) = {left_arc, right_arc, flat_top};
cylinder = news; Plane Surface(cylinder) = {cylinder_loop};

// Body 2: the block, counter-clockwise from its lower left corner; the origin splits its top.
foot_left  = newp; Point(foot_left)  = {-Width, -Height, 0};
foot_right = newp; Point(foot_right) = {Width, -Height, 0};
top_right  = newp; Point(top_right)  = {Width, 0, 0};
origin     = newp; Point(origin)     = {0, 0, 0};
top_left   = newp; Point(top_left)   = {-Width, 0, 0};
block_bottom    = newl; Line(block_bottom)    = {foot_left, foot_right};
block_right     = newl; Line(block_right)     = {foot_right, top_right};
block_top_right = newl; Line(block_top_right) = {top_right, origin};
block_top_left  = newl; Line(block_top_left)  = {origin, top_left};
block_left      = newl; Line(block_left)      = {top_left, foot_left};
block_loop = newll;
Curve Loop(block_loop) = {block_bottom, block_right, block_top_right, block_top_left, block_left};
block = news; Plane Surface(block) = {block_loop};

contact_points[]  = {pole, origin};
cylinder_curves[] = {left_arc, right_arc, flat_top};
cylinder_points[] = {left, pole, right};
block_curves[]    = {block_bottom, block_right, block_top_right, block_top_left, block_left};
block_points[]    = {foot_left, foot_right, top_right, origin, top_left};
Include "contact_zone_sizes.geo.inc";

Physical Surface("cylinder", 1)       = {cylinder};
Physical Surface("block", 2)          = {block};
Physical Curve("cylinder top", 1)     = {flat_top};
Physical Curve("cylinder arc", 2)     = {left_arc, right_arc};
Physical Curve("block top", 3)        = {block_top_right, block_top_left};
Physical Curve("block bottom", 4)     = {block_bottom};
Physical Curve("block left side", 5)  = {block_left};
Physical Curve("block right side", 6) = {block_right};
