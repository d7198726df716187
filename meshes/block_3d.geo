// A rectangular box for dyncontact's 3D meshes (read_gmsh_solid_mesh): [X0, X0 + LX] x
// [Y0, Y0 + LY] x [Z0, Z0 + LZ], NX x NY x NZ equal hexahedra, built by extruding a point into a
// line, the line into a rectangle and the rectangle into the box, with layers and recombination.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   LX, LY, LZ   the edges [length], > 0                                                 (2, 2, 1)
//   X0, Y0, Z0   the corner with the smallest coordinates [length]                        (0, 0, 0)
//   NX, NY, NZ   cells along x, y and z, integers >= 1                                    (4, 4, 2)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Volume  1      the body
//   Physical Surface 1, 2   the faces x = X0, x = X0 + LX
//   Physical Surface 3, 4   the faces y = Y0, y = Y0 + LY
//   Physical Surface 5, 6   the bottom z = Z0 and the top z = Z0 + LZ

DefineConstant[
  LX = {2, Name "Parameters/LX"}, LY = {2, Name "Parameters/LY"}, LZ = {1, Name "Parameters/LZ"},
  X0 = {0, Name "Parameters/X0"}, Y0 = {0, Name "Parameters/Y0"}, Z0 = {0, Name "Parameters/Z0"},
  NX = {4, Name "Parameters/NX"}, NY = {4, Name "Parameters/NY"}, NZ = {2, Name "Parameters/NZ"}
];

If (LX <= 0 || LY <= 0 || LZ <= 0)
  Error("block_3d.geo: LX = %g, LY = %g, LZ = %g, but all must be > 0", LX, LY, LZ);
EndIf
If (NX < 1 || NX != Round(NX) || NY < 1 || NY != Round(NY) || NZ < 1 || NZ != Round(NZ))
  Error("block_3d.geo: NX = %g, NY = %g, NZ = %g, but all must be integers >= 1", NX, NY, NZ);
EndIf

corner = newp; Point(corner) = {X0, Y0, Z0};
edge[] = Extrude {LX, 0, 0} { Point{corner}; Layers{NX}; };
face[] = Extrude {0, LY, 0} { Curve{edge[1]}; Layers{NY}; Recombine; };
box[]  = Extrude {0, 0, LZ} { Surface{face[1]}; Layers{NZ}; Recombine; };
// box[0] is the top, box[1] the volume, box[2..5] the sides extruded from the rectangle's edges:
// y = Y0, x = X0 + LX, y = Y0 + LY, x = X0 (the rectangle's boundary in order).

Physical Volume("block", 1)  = {box[1]};
Physical Surface("x0", 1)    = {box[5]};
Physical Surface("x1", 2)    = {box[3]};
Physical Surface("y0", 3)    = {box[2]};
Physical Surface("y1", 4)    = {box[4]};
Physical Surface("bottom", 5) = {face[1]};
Physical Surface("top", 6)   = {box[0]};
