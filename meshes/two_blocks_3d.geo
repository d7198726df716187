// Two rectangular boxes stacked along z for dyncontact's 3D contact tests: block 1
// [0, LX] x [0, LY] x [0, H1] with NX1 x NY1 x NZ1 hexahedra, and block 2
// [0, LX] x [0, LY] x [H1 + Gap, H1 + Gap + H2] with NX2 x NY2 x NZ2. The facing faces (the top
// of block 1, the bottom of block 2) have matching nodes if NX1 = NX2 and NY1 = NY2; otherwise
// only their corners coincide (non-matching). Built as meshes/block_3d.geo, by extruding a point
// into a line, the line into a rectangle and the rectangle into a box, with layers and
// recombination.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   LX, LY        the edges across [length], > 0                                        (2, 2)
//   H1, H2        the heights of blocks 1 and 2 [length], > 0                           (1, 1)
//   Gap           the distance between the facing faces [length], >= 0                     (0)
//   NX1, NY1, NZ1 cells of block 1 along x, y and z, integers >= 1                     (4, 4, 2)
//   NX2, NY2, NZ2 cells of block 2 along x, y and z, integers >= 1                     (4, 4, 2)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Volume  1, 2     blocks 1 and 2
//   Physical Surface 1, 2     block 1's faces x = 0, x = LX
//   Physical Surface 3, 4     block 1's faces y = 0, y = LY
//   Physical Surface 5, 6     block 1's bottom z = 0 and top z = H1
//   Physical Surface 7, 8     block 2's faces x = 0, x = LX
//   Physical Surface 9, 10    block 2's faces y = 0, y = LY
//   Physical Surface 11, 12   block 2's bottom z = H1 + Gap and top

DefineConstant[
  LX = {2, Name "Parameters/LX"}, LY = {2, Name "Parameters/LY"},
  H1 = {1, Name "Parameters/H1"}, H2 = {1, Name "Parameters/H2"}, Gap = {0, Name "Parameters/Gap"},
  NX1 = {4, Name "Parameters/NX1"}, NY1 = {4, Name "Parameters/NY1"},
  NZ1 = {2, Name "Parameters/NZ1"}, NX2 = {4, Name "Parameters/NX2"},
  NY2 = {4, Name "Parameters/NY2"}, NZ2 = {2, Name "Parameters/NZ2"}
];

If (LX <= 0 || LY <= 0 || H1 <= 0 || H2 <= 0 || Gap < 0)
  Error("two_blocks_3d.geo: LX, LY, H1, H2 must be > 0 and Gap >= 0");
EndIf
If (NX1 < 1 || NX1 != Round(NX1) || NY1 < 1 || NY1 != Round(NY1) || NZ1 < 1 || NZ1 != Round(NZ1))
  Error("two_blocks_3d.geo: NX1 = %g, NY1 = %g, NZ1 = %g, but all must be integers >= 1", NX1, NY1, NZ1);
EndIf
If (NX2 < 1 || NX2 != Round(NX2) || NY2 < 1 || NY2 != Round(NY2) || NZ2 < 1 || NZ2 != Round(NZ2))
  Error("two_blocks_3d.geo: NX2 = %g, NY2 = %g, NZ2 = %g, but all must be integers >= 1", NX2, NY2, NZ2);
EndIf

// Two OpenCASCADE boxes, not fused: with Gap = 0 the facing faces coincide but stay two surfaces,
// and their nodes stay two sets. Meshed as structured hexahedra (transfinite, recombined).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, LX, LY, H1};
Box(2) = {0, 0, H1 + Gap, LX, LY, H2};
eps = 1e-6 * (LX + LY + H1 + H2);
For b In {1:2}
  n[] = {NX1, NY1, NZ1};
  If (b == 2)
    n[] = {NX2, NY2, NZ2};
  EndIf
  // Each edge of box b (its own curves only: with Gap = 0 the other box's edges lie on the same
  // lines) gets the cell count of the axis it runs along.
  edges[] = Unique(Abs(Boundary{Boundary{Volume{b};}}));
  For e In {0:#edges[] - 1}
    box[] = BoundingBox Curve{edges[e]};
    For axis In {0:2}
      If (box[axis + 3] - box[axis] > eps)
        Transfinite Curve {edges[e]} = n[axis] + 1;
      EndIf
    EndFor
  EndFor
  faces[] = Abs(Boundary{Volume{b};});
  Transfinite Surface {faces[]};
  Recombine Surface {faces[]};
  Transfinite Volume {b};
  // The faces of box b (OpenCASCADE's order: x = min, x = max, y = min, y = max, z = min,
  // z = max), as physical surfaces 6 (b - 1) + 1 .. 6 (b - 1) + 6.
  For f In {0:5}
    Physical Surface(6 * (b - 1) + f + 1) = {faces[f]};
  EndFor
  Physical Volume(b) = {b};
EndFor
