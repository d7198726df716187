// Two identical solid cylinders (rods) on the axis for dyncontact, flat ends facing: rod 1
// (body 1) below, z in [-Gap/2 - L, -Gap/2], rod 2 (body 2) above, z in [Gap/2, Gap/2 + L], both
// of radius Rad; rod 2 is the mirror image of rod 1 about z = 0 node by node (the same
// transfinite divisions), so node-to-node contact pairs the facing end faces. The rod-on-rod
// impact of the paper's section 6.2 as an axisymmetric continuum; with Gap = 0 the end faces touch
// at t = 0 and their centroids coincide (issue 25, cases 21 and 22).
//
// Parameters, settable from outside (gmsh -setnumber NAME VALUE, or dyncontact's read_gmsh_mesh):
//   L    length of each rod [length]                                                      (10)
//   Rad  radius of each rod [length]                                                      (0.5)
//   Gap  axial gap between the end faces [length], >= 0                                   (0)
//   NL   cells along each rod (integer >= 1)                                              (100)
//   NR   cells across the radius (integer >= 1)                                           (3)
//
// Physical groups: surfaces 1, 2 the rods; curve 1 the axis; curves 2 (top of rod 1) and 3
// (bottom of rod 2) the facing end faces; 4, 6 the sides; 5, 7 the far ends.
DefineConstant[
  L   = {10,  Name "Parameters/L"},
  Rad = {0.5, Name "Parameters/Rad"},
  Gap = {0,   Name "Parameters/Gap"},
  NL  = {100, Name "Parameters/NL"},
  NR  = {3,   Name "Parameters/NR"}
];
z1 = -Gap/2; z0 = z1 - L;
z2 = Gap/2;  z3 = z2 + L;
Point(1) = {0, z0, 0}; Point(2) = {Rad, z0, 0}; Point(3) = {Rad, z1, 0}; Point(4) = {0, z1, 0};
Point(5) = {0, z2, 0}; Point(6) = {Rad, z2, 0}; Point(7) = {Rad, z3, 0}; Point(8) = {0, z3, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = NR + 1;
Transfinite Curve{2, 4, 6, 8} = NL + 1;
Transfinite Surface{1}; Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface("rod 1", 1) = {1};
Physical Surface("rod 2", 2) = {2};
Physical Curve("axis", 1) = {4, 8};
Physical Curve("top of rod 1", 2) = {3};
Physical Curve("bottom of rod 2", 3) = {5};
Physical Curve("side of rod 1", 4) = {2};
Physical Curve("bottom of rod 1", 5) = {1};
Physical Curve("side of rod 2", 6) = {6};
Physical Curve("top of rod 2", 7) = {7};
