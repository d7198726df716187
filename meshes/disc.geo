// Plane-strain disc for dyncontact (Problem/geometry = plane strain mesh): the full disc of radius
// R centred at (CentreX, CentreY) in the (x, y) plane. All quadrilaterals, from a transfinite
// O-grid: a core square (corners at 0.45 R from the centre, on the diagonals) and four curved
// blocks between its sides and the four quarter arcs of the circle, the arcs' ends at 45, 135, 225
// and 315 degrees. The lowest point of the disc, (CentreX, CentreY - R), is the middle of the
// bottom block's arc, where a disc falling onto a plane below it first touches. Uniform along the
// circle; along every radial line the elements shrink toward the circle by SurfaceGrading.
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's Mesh/geo
// parameters):
//   R               disc radius [length], > 0                                             (20)
//   CentreX         x of the centre [length]                                              (0)
//   CentreY         y of the centre [length]                                              (25)
//   Divisions       element edges on each quarter arc at refinement 0, integer >= 1        (6)
//   RadialDivisions element layers between the core and the circle, integer >= 1          (4)
//   Refinement      each level doubles Divisions and RadialDivisions, integer >= 0         (0)
//   SurfaceGrading  innermost / outermost element layer along each radial line, >= 1      (1.5)
//
// Physical groups (read by dyncontact as material and boundary ids, see gmsh_mesh.h):
//   Physical Surface 1      the body
//   Physical Curve   2      the circle (the disc's surface), as the sphere meshes number it

DefineConstant[
  R               = {20,  Name "Parameters/R"},
  CentreX         = {0,   Name "Parameters/CentreX"},
  CentreY         = {25,  Name "Parameters/CentreY"},
  Divisions       = {6,   Name "Parameters/Divisions"},
  RadialDivisions = {4,   Name "Parameters/RadialDivisions"},
  Refinement      = {0,   Name "Parameters/Refinement"},
  SurfaceGrading  = {1.5, Name "Parameters/SurfaceGrading"}
];

If (R <= 0)
  Error("disc.geo: R = %g, but the radius must be > 0", R);
EndIf
If (Divisions < 1 || Divisions != Round(Divisions))
  Error("disc.geo: Divisions = %g, but it must be an integer >= 1", Divisions);
EndIf
If (RadialDivisions < 1 || RadialDivisions != Round(RadialDivisions))
  Error("disc.geo: RadialDivisions = %g, but it must be an integer >= 1", RadialDivisions);
EndIf
If (Refinement < 0 || Refinement != Round(Refinement))
  Error("disc.geo: Refinement = %g, but it must be an integer >= 0", Refinement);
EndIf
If (SurfaceGrading < 1)
  Error("disc.geo: SurfaceGrading = %g, but it must be >= 1", SurfaceGrading);
EndIf

n_arc    = Divisions * 2^Refinement;
n_radial = RadialDivisions * 2^Refinement;
radial_growth = 1;
If (n_radial > 1)
  radial_growth = SurfaceGrading^(1 / (n_radial - 1));
EndIf

centre = newp; Point(centre) = {CentreX, CentreY, 0};
core_half = 0.45 * R / Sqrt(2);
For k In {0:3}
  angle = Pi / 4 + k * Pi / 2;
  core[k] = newp;
  Point(core[k]) = {CentreX + Sqrt(2) * core_half * Cos(angle),
                    CentreY + Sqrt(2) * core_half * Sin(angle), 0};
  rim[k] = newp;
  Point(rim[k]) = {CentreX + R * Cos(angle), CentreY + R * Sin(angle), 0};
EndFor
For k In {0:3}
  next = (k + 1) % 4;
  arc[k]  = newl; Circle(arc[k]) = {rim[k], centre, rim[next]};
  side[k] = newl; Line(side[k]) = {core[k], core[next]};
  ray[k]  = newl; Line(ray[k]) = {core[k], rim[k]};
EndFor
Transfinite Curve {arc[], side[]} = n_arc + 1;
Transfinite Curve {ray[]} = n_radial + 1 Using Progression 1 / radial_growth;

core_loop = newll; Curve Loop(core_loop) = {side[]};
core_block = news; Plane Surface(core_block) = {core_loop};
blocks[] = {core_block};
For k In {0:3}
  next = (k + 1) % 4;
  loop = newll; Curve Loop(loop) = {ray[k], arc[k], -ray[next], -side[k]};
  block = news; Plane Surface(block) = {loop};
  blocks[] += {block};
EndFor
Transfinite Surface {blocks[]};
Recombine Surface {blocks[]};

Physical Surface("body 1", 1) = {blocks[]};
Physical Curve("surface of body 1", 2) = {arc[]};
