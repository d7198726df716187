// A rectangular block for dyncontact: [X0, X0 + Width] x [Y0, Y0 + Height] in the (x, y) plane,
// a structured grid of NX x NY equal quadrilaterals (transfinite, recombined). In plane strain
// (Problem/geometry = plane strain mesh) the cross-section of a long block; as an axisymmetric
// mesh with X0 = 0 a solid cylinder of radius Width on the axis (curve 1 is then the axis).
// A block [0, W] with NX cells has the nodes of the right half of the block [-W, W] with 2 NX
// cells: the half block on a symmetry plane x = 0 (Boundary/Symmetry k, boundary 1) reproduces the
// whole one.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   Width   extent in x [length], > 0                                                     (2)
//   Height  extent in y [length], > 0                                                     (1)
//   X0, Y0  the lower left corner [length]                                                (0, 0)
//   NX, NY  cells along x and along y, integers >= 1                                      (8, 4)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Surface 1      the body
//   Physical Curve   1      the left side x = X0 (the axis of an axisymmetric cylinder)
//   Physical Curve   2      the bottom y = Y0
//   Physical Curve   3      the right side x = X0 + Width
//   Physical Curve   4      the top y = Y0 + Height

DefineConstant[
  Width  = {2, Name "Parameters/Width"},
  Height = {1, Name "Parameters/Height"},
  X0     = {0, Name "Parameters/X0"},
  Y0     = {0, Name "Parameters/Y0"},
  NX     = {8, Name "Parameters/NX"},
  NY     = {4, Name "Parameters/NY"}
];

If (Width <= 0 || Height <= 0)
  Error("block.geo: Width = %g, Height = %g, but both must be > 0", Width, Height);
EndIf
If (NX < 1 || NX != Round(NX) || NY < 1 || NY != Round(NY))
  Error("block.geo: NX = %g, NY = %g, but both must be integers >= 1", NX, NY);
EndIf

p1 = newp; Point(p1) = {X0, Y0, 0};
p2 = newp; Point(p2) = {X0 + Width, Y0, 0};
p3 = newp; Point(p3) = {X0 + Width, Y0 + Height, 0};
p4 = newp; Point(p4) = {X0, Y0 + Height, 0};
bottom = newl; Line(bottom) = {p1, p2};
right  = newl; Line(right)  = {p2, p3};
top    = newl; Line(top)    = {p3, p4};
left   = newl; Line(left)   = {p4, p1};
Transfinite Curve {bottom, top} = NX + 1;
Transfinite Curve {right, left} = NY + 1;
loop = newll; Curve Loop(loop) = {bottom, right, top, left};
block = news; Plane Surface(block) = {loop};
Transfinite Surface {block};
Recombine Surface {block};

Physical Surface("block", 1) = {block};
Physical Curve("left", 1)   = {left};
Physical Curve("bottom", 2) = {bottom};
Physical Curve("right", 3)  = {right};
Physical Curve("top", 4)    = {top};
