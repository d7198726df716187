// Two rectangular blocks stacked in the (x, y) plane for dyncontact: block 1 (body 1)
// [X0, X0 + Width] x [-Height, 0] below, block 2 (body 2) [X0, X0 + Width] x [Gap, Gap + Height]
// above, each a structured grid of equal quadrilaterals (transfinite, recombined) with its own
// number of cells along x, so that the facing faces y = 0 and y = Gap need not match: the contact
// patch test (a uniform pressure must cross non-matching faces unchanged). In plane strain the
// cross-sections of two long blocks; as an axisymmetric mesh with X0 = 0 two solid cylinders on
// the axis, end to end.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   Width   extent in x [length], > 0                                                     (1)
//   Width1  extent in x of block 1 alone [length], > 0; 0: Width (a narrower block 1 leaves
//           block 2's bottom face reaching beyond the end of block 1's top face)          (0)
//   Height  extent in y of each block [length], > 0                                       (0.5)
//   Gap     distance between the facing faces [length], >= 0                              (0)
//   X0      x of the left sides [length]                                                  (0)
//   NX1     cells of block 1 along x, integer >= 1                                        (4)
//   NX2     cells of block 2 along x, integer >= 1                                        (5)
//   NY      cells of each block along y, integer >= 1                                     (2)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Surface 1, 2   block 1, block 2
//   Physical Curve   1      the left side x = X0 of block 1; with OnAxis = 1 also that of block 2
//                           (the axis, which dyncontact requires to be curve 1 in axisymmetry)
//   Physical Curve   2      the bottom of block 1, y = -Height
//   Physical Curve   3      the top of block 1, y = 0 (facing block 2)
//   Physical Curve   4      the bottom of block 2, y = Gap (facing block 1)
//   Physical Curve   5      the top of block 2, y = Gap + Height
//   Physical Curve   6, 7   the right sides x = X0 + Width of block 1, block 2
//   Physical Curve   8      the left side of block 2 (OnAxis = 0: in plane strain each physical
//                           curve bounds one body)

DefineConstant[
  Width  = {1,   Name "Parameters/Width"},
  Width1 = {0,   Name "Parameters/Width1"},
  Height = {0.5, Name "Parameters/Height"},
  Gap    = {0,   Name "Parameters/Gap"},
  X0     = {0,   Name "Parameters/X0"},
  NX1    = {4,   Name "Parameters/NX1"},
  NX2    = {5,   Name "Parameters/NX2"},
  NY     = {2,   Name "Parameters/NY"},
  OnAxis = {0,   Name "Parameters/OnAxis"}
];

If (Width1 < 0)
  Error("two_blocks.geo: Width1 = %g, but it must be > 0 (or 0: Width)", Width1);
EndIf
If (Width <= 0 || Height <= 0 || Gap < 0)
  Error("two_blocks.geo: Width = %g, Height = %g, Gap = %g, but Width and Height must be > 0 and Gap >= 0", Width, Height, Gap);
EndIf
If (NX1 < 1 || NX1 != Round(NX1) || NX2 < 1 || NX2 != Round(NX2) || NY < 1 || NY != Round(NY))
  Error("two_blocks.geo: NX1 = %g, NX2 = %g, NY = %g, but all must be integers >= 1", NX1, NX2, NY);
EndIf

For b In {0:1}
  y0 = (b == 0) ? -Height : Gap;
  p1 = newp; Point(p1) = {X0, y0, 0};
  w = (b == 0 && Width1 > 0) ? Width1 : Width;
  p2 = newp; Point(p2) = {X0 + w, y0, 0};
  p3 = newp; Point(p3) = {X0 + w, y0 + Height, 0};
  p4 = newp; Point(p4) = {X0, y0 + Height, 0};
  bottom[b] = newl; Line(bottom[b]) = {p1, p2};
  right[b]  = newl; Line(right[b])  = {p2, p3};
  top[b]    = newl; Line(top[b])    = {p3, p4};
  left[b]   = newl; Line(left[b])   = {p4, p1};
  Transfinite Curve {bottom[b], top[b]} = ((b == 0) ? NX1 : NX2) + 1;
  Transfinite Curve {right[b], left[b]} = NY + 1;
  loop = newll; Curve Loop(loop) = {bottom[b], right[b], top[b], left[b]};
  block[b] = news; Plane Surface(block[b]) = {loop};
  Transfinite Surface {block[b]};
  Recombine Surface {block[b]};
EndFor

Physical Surface("block 1", 1) = {block[0]};
Physical Surface("block 2", 2) = {block[1]};
If (OnAxis == 1)
  Physical Curve("left sides (the axis)", 1) = {left[0], left[1]};
Else
  Physical Curve("left of block 1", 1) = {left[0]};
  Physical Curve("left of block 2", 8) = {left[1]};
EndIf
Physical Curve("bottom of block 1", 2) = {bottom[0]};
Physical Curve("top of block 1", 3)    = {top[0]};
Physical Curve("bottom of block 2", 4) = {bottom[1]};
Physical Curve("top of block 2", 5)    = {top[1]};
Physical Curve("right of block 1", 6)  = {right[0]};
Physical Curve("right of block 2", 7)  = {right[1]};
