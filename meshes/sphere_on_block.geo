// An axisymmetric sphere above a thick cylindrical block for dyncontact (the Hertz half-space
// limit): body 1 is the sphere of radius R, above, with its centre on the axis at z = Gap + R and
// its contact pole at z = Gap; body 2 is the block r <= BlockRadius, -BlockHeight <= z <= 0, whose
// top face z = 0 is the contact surface, its contact point at the origin. The sphere is built by
// the macro of sphere.geo (its surface edges grow by PoleGrading from the contact pole, which
// faces down); the block's nodes have nothing to do with the sphere's (non-matching by
// construction).
//
// The block is all quadrilaterals from three transfinite blocks (no size field): a square patch
// [0, ContactZone] x [-ContactZone, 0] at the contact point with a uniform grid of n x n cells
// (n = ContactZoneDivisions * 2^Refinement), and two blocks that fan out from its right and bottom
// edges to the block's side r = BlockRadius and bottom z = -BlockHeight, split along the line from
// the patch's corner (ContactZone, -ContactZone) to the block's corner (BlockRadius,
// -BlockHeight). Across the fan, n cells as on the patch; along it, element layers that grow
// geometrically by the factor q = 1 + 1/n from the patch outward (the first of about
// ContactZone/n), so that every cell stays about as long as it is wide (a polar grid whose
// angular cell size ~ distance / n): Ceil(ln(max(BlockRadius, BlockHeight)/ContactZone) / ln q)
// layers reach the outer boundary. The contact zone is thus resolved uniformly by cells of size
// ContactZone/n, and the cells grow with the distance from the contact point.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   R                     sphere radius [length], > 0                                       (8)
//   Gap                   initial gap between the sphere's contact pole and the block's top
//                         face [length], >= 0 (0: touching)                                  (4)
//   BlockRadius           radius of the block [length], >= 2 ContactZone                    (40)
//   BlockHeight           height of the block [length], >= 2 ContactZone                    (40)
//   ContactZone           side of the uniformly meshed square at the contact point [length],
//                         > 0                                                                (2)
//   ContactZoneDivisions  cells along each side of that square at refinement 0, integer
//                         >= 1                                                               (8)
//   and Divisions, RadialDivisions, Refinement, PoleGrading, SurfaceGrading, CoreOffset as in
//   sphere.geo: the sphere's mesh, and Refinement doubles ContactZoneDivisions too.
//
// The block's defaults, 5 R wide and 5 R deep, are several times R and some 50 times the Hertz
// contact radius of the paper's impacts (below 1); how far the block's compliance is from the
// half-space's is for the impact runs to measure. Larger blocks cost only a few layers (their
// number grows with the logarithm of the size).
//
// Resolution at the contact point (cells of sphere + block; chord of the sphere's surface edge at
// its contact pole; the block's top face edge at the contact point):
//   defaults (PoleGrading 3)                          216 + 480 cells, edges 0.57, 0.25
//   PoleGrading 10, CoreOffset 0.3                    216 + 480 cells, edges 0.26, 0.25
// Each Refinement level quadruples the sphere's cells and halves both edges.
//
// Physical groups:
//   Physical Surface 1      the sphere (body 1)
//   Physical Surface 2      the block (body 2)
//   Physical Curve   1      the axis r = 0 (both bodies)
//   Physical Curve   2      the sphere surface (the surface of body 1)
//   Physical Curve   3      the block's top face z = 0 (the contact surface of body 2)
//   Physical Curve   4      the block's side r = BlockRadius
//   Physical Curve   5      the block's bottom z = -BlockHeight

SphereMacroOnly = 1;
Include "sphere.geo";

DefineConstant[
  R                    = {8,  Name "Parameters/R"},
  Gap                  = {4,  Name "Parameters/Gap"},
  BlockRadius          = {40, Name "Parameters/BlockRadius"},
  BlockHeight          = {40, Name "Parameters/BlockHeight"},
  ContactZone          = {2,  Name "Parameters/ContactZone"},
  ContactZoneDivisions = {8,  Name "Parameters/ContactZoneDivisions"}
];
If (R <= 0)
  Error("sphere_on_block.geo: R = %g, but the radius must be > 0", R);
EndIf
If (Gap < 0)
  Error("sphere_on_block.geo: Gap = %g, but the bodies overlap unless it is >= 0", Gap);
EndIf
If (ContactZone <= 0)
  Error("sphere_on_block.geo: ContactZone = %g, but it must be > 0", ContactZone);
EndIf
If (BlockRadius < 2 * ContactZone)
  Error("sphere_on_block.geo: BlockRadius = %g, but it must be >= 2 ContactZone = %g",
        BlockRadius, 2 * ContactZone);
EndIf
If (BlockHeight < 2 * ContactZone)
  Error("sphere_on_block.geo: BlockHeight = %g, but it must be >= 2 ContactZone = %g",
        BlockHeight, 2 * ContactZone);
EndIf
If (ContactZoneDivisions < 1 || ContactZoneDivisions != Round(ContactZoneDivisions))
  Error("sphere_on_block.geo: ContactZoneDivisions = %g, but it must be an integer >= 1",
        ContactZoneDivisions);
EndIf

// Body 1: the sphere above, contact pole facing down.
sphere_radius    = R;
sphere_divisions = Divisions;
sphere_centre_z  = Gap + R;
sphere_pole_side = -1;
sphere_body      = 1;
Call SphereBody;

// Body 2: the block. Cells across the square patch and the fan, the growth factor of the layers
// and their number.
n_zone      = ContactZoneDivisions * 2^Refinement;
layer_growth = 1 + 1 / n_zone;
n_layers    = Ceil(Log(Max(BlockRadius, BlockHeight) / ContactZone) / Log(layer_growth));

c = ContactZone;
contact_point = newp; Point(contact_point) = {0, 0, 0};
zone_top      = newp; Point(zone_top)      = {c, 0, 0};
zone_corner   = newp; Point(zone_corner)   = {c, -c, 0};
zone_axis     = newp; Point(zone_axis)     = {0, -c, 0};
block_top     = newp; Point(block_top)     = {BlockRadius, 0, 0};
block_corner  = newp; Point(block_corner)  = {BlockRadius, -BlockHeight, 0};
block_axis    = newp; Point(block_axis)    = {0, -BlockHeight, 0};

// The square patch, its edges oriented away from the contact point.
zone_top_edge   = newl; Line(zone_top_edge)   = {contact_point, zone_top};
zone_right_edge = newl; Line(zone_right_edge) = {zone_top, zone_corner};
zone_axis_edge  = newl; Line(zone_axis_edge)  = {contact_point, zone_axis};
zone_bottom_edge = newl; Line(zone_bottom_edge) = {zone_axis, zone_corner};
// The fan: lines along it oriented outward (the layers grow along them), lines across it.
top_edge    = newl; Line(top_edge)    = {zone_top, block_top};
diagonal    = newl; Line(diagonal)    = {zone_corner, block_corner};
axis_edge   = newl; Line(axis_edge)   = {zone_axis, block_axis};
side_edge   = newl; Line(side_edge)   = {block_top, block_corner};
bottom_edge = newl; Line(bottom_edge) = {block_axis, block_corner};

Transfinite Curve {zone_top_edge, zone_right_edge, zone_axis_edge, zone_bottom_edge,
                   side_edge, bottom_edge} = n_zone + 1;
Transfinite Curve {top_edge, diagonal, axis_edge} = n_layers + 1 Using Progression layer_growth;

zone_loop  = newll;
Curve Loop(zone_loop)  = {zone_top_edge, zone_right_edge, -zone_bottom_edge, -zone_axis_edge};
right_loop = newll;
Curve Loop(right_loop) = {top_edge, side_edge, -diagonal, -zone_right_edge};
lower_loop = newll;
Curve Loop(lower_loop) = {zone_bottom_edge, diagonal, -bottom_edge, -axis_edge};

zone_block  = news; Plane Surface(zone_block)  = {zone_loop};
right_block = news; Plane Surface(right_block) = {right_loop};
lower_block = news; Plane Surface(lower_block) = {lower_loop};
block_blocks[] = {zone_block, right_block, lower_block};
Transfinite Surface {block_blocks[]};
Recombine Surface {block_blocks[]};

Physical Surface("body 2", 2) = {block_blocks[]};
Physical Curve("surface of body 2", 3) = {zone_top_edge, top_edge};
Physical Curve("side of body 2", 4) = {side_edge};
Physical Curve("bottom of body 2", 5) = {bottom_edge};
axis_curves[] += {zone_axis_edge, axis_edge};

Physical Curve("axis", 1) = {axis_curves[]};
