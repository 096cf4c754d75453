// A U-shaped body for tests/verification/self_contact.py: a base
// [-3, 3] x [0, 1] with two arms [-3, -0.5] x [1, 4] and [0.5, 3] x [1, 4]
// (a slot 1 wide between them); structured quadrilaterals, the left half
// the mirror image of the right one but for one cell more along the left
// arm's inner face (so that the arms' nodes do not meet); the right half
// alone for the half model (the cut x = 0 a symmetry plane):
//   gmsh -2 u_shape.geo -o u_shape.msh
//   gmsh -2 u_shape.geo -setnumber half 1 -o u_shape_half.msh
//   gmsh -2 u_shape.geo -setnumber split 1 -o u_shape_split.msh
// Physical groups (lines): 1 the arms' inner faces x = -0.5, 0.5 (the slot),
// 2 the left arm's top, 6 the right arm's top, 3 the bottom y = 0, 4 the
// cut x = 0 (half model), 7 the right arm's outer face x = 3, 8 the left
// one's, 5 the rest of the boundary; surface 1 the body. With split = 1
// the slot's faces are two boundaries, 9 the right arm's and 10 the left
// arm's (the same body as a two-body pair would see it).
DefineConstant[ half = {0, Name "1: the right half only"},
                split = {0, Name "1: the slot's faces as boundaries 9, 10"},
                n    = {4, Name "cells per unit length"} ];
Mesh.MshFileVersion = 2.2;
Point(1) = {0, 0, 0};
Point(4) = {0, 1, 0};
Line(5) = {1, 4};
Transfinite Curve{5} = n + 1;
For side In {1 : (half == 1 ? 1 : 2)}
  s = (side == 1 ? 1 : -1);
  o = 10 * side;
  Point(o + 2) = {0.5 * s, 0, 0}; Point(o + 3) = {3 * s, 0, 0};
  Point(o + 5) = {0.5 * s, 1, 0}; Point(o + 6) = {3 * s, 1, 0};
  Point(o + 7) = {0.5 * s, 4, 0}; Point(o + 8) = {3 * s, 4, 0};
  Line(o + 1) = {1, o + 2};     Line(o + 2) = {o + 2, o + 3};
  Line(o + 3) = {4, o + 5};     Line(o + 4) = {o + 5, o + 6};
  Line(o + 6) = {o + 2, o + 5}; Line(o + 7) = {o + 3, o + 6};
  Line(o + 8) = {o + 5, o + 7}; Line(o + 9) = {o + 6, o + 8};
  Line(o + 0) = {o + 7, o + 8};
  Transfinite Curve{o + 1, o + 3} = Round(0.5 * n) + 1;
  Transfinite Curve{o + 2, o + 4, o + 0} = Round(2.5 * n) + 1;
  Transfinite Curve{o + 6, o + 7} = n + 1;
  Transfinite Curve{o + 8, o + 9} = 3 * n + side;
  Curve Loop(o + 1) = {o + 1, o + 6, -(o + 3), -5};
  Curve Loop(o + 2) = {o + 2, o + 7, -(o + 4), -(o + 6)};
  Curve Loop(o + 3) = {o + 4, o + 9, -(o + 0), -(o + 8)};
  Plane Surface(o + 1) = {o + 1};
  Plane Surface(o + 2) = {o + 2};
  Plane Surface(o + 3) = {o + 3};
  Transfinite Surface{o + 1, o + 2, o + 3};
  Recombine Surface{o + 1, o + 2, o + 3};
EndFor
If (half == 1)
  Physical Curve(1) = {18};
  Physical Curve(6) = {10};
  Physical Curve(3) = {11, 12};
  Physical Curve(4) = {5};
  Physical Curve(7) = {19};
  Physical Curve(5) = {13, 17};
  Physical Surface(1) = {11, 12, 13};
Else
  If (split == 1)
    Physical Curve(9) = {18};
    Physical Curve(10) = {28};
  Else
    Physical Curve(1) = {18, 28};
  EndIf
  Physical Curve(2) = {20};
  Physical Curve(6) = {10};
  Physical Curve(3) = {11, 12, 21, 22};
  Physical Curve(7) = {19};
  Physical Curve(8) = {29};
  Physical Curve(5) = {13, 17, 23, 27};
  Physical Surface(1) = {11, 12, 13, 21, 22, 23};
EndIf
