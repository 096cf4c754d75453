// A tube crushed flat between two plates until its inner surface closes
// (tests/verification/self_contact.py): inner radius 0.6, outer 1, one
// layer of hexahedra 0.1 thick along z (plane strain through symmetry on
// both ends). The right half x >= 0 (the cut x = 0 a symmetry plane) is
// the self-contact model: the inner surface's upper half meets its lower
// half at y = 0. With quarter = 1 only y >= 0: the reference, the cut
// y = 0 a symmetry plane and the inner surface against a rigid wall there.
//   gmsh -3 tube.geo -o tube_half.msh
//   gmsh -3 tube.geo -setnumber quarter 1 -o tube_quarter.msh
// With planar = 1 the cross-section alone, a ring in plane strain, the
// same physical groups as curves (no ends 3, 4):
//   gmsh -2 tube.geo -setnumber planar 1 -o ring_half.msh
//   gmsh -2 tube.geo -setnumber planar 1 -setnumber quarter 1 \
//     -o ring_quarter.msh
// Physical groups (surfaces): 1 inner, 2 outer, 3 the end z = 0, 4 the
// end z = 0.1, 5 the cut x = 0, 6 the cut y = 0 (quarter); volume 1.
DefineConstant[ quarter = {0, Name "1: y >= 0 only"},
                planar = {0, Name "1: the cross-section (2D)"},
                n = {12, Name "cells along a quarter arc"},
                m = {3, Name "cells across the wall"} ];
Mesh.MshFileVersion = 2.2;
Mesh.RecombineAll = 1;
ri = 0.6; ro = 1.0; dz = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {0, ri, 0}; Point(3) = {0, ro, 0};
Point(4) = {ri, 0, 0}; Point(5) = {ro, 0, 0};
Point(6) = {0, -ri, 0}; Point(7) = {0, -ro, 0};
Circle(1) = {2, 1, 4}; Circle(2) = {3, 1, 5};
Line(3) = {2, 3}; Line(4) = {4, 5};
Transfinite Curve{1, 2} = n + 1; Transfinite Curve{3, 4} = m + 1;
Curve Loop(1) = {3, 2, -4, -1}; Plane Surface(1) = {1};
Transfinite Surface{1}; Recombine Surface{1};
If (quarter == 0)
  Circle(5) = {4, 1, 6}; Circle(6) = {5, 1, 7}; Line(7) = {6, 7};
  Transfinite Curve{5, 6} = n + 1; Transfinite Curve{7} = m + 1;
  Curve Loop(2) = {4, 6, -7, -5}; Plane Surface(2) = {2};
  Transfinite Surface{2}; Recombine Surface{2};
EndIf
If (planar == 1 && quarter == 0)
  Physical Curve(1) = {1, 5};
  Physical Curve(2) = {2, 6};
  Physical Curve(5) = {3, 7};
  Physical Surface(1) = {1, 2};
EndIf
If (planar == 1 && quarter == 1)
  Physical Curve(1) = {1};
  Physical Curve(2) = {2};
  Physical Curve(5) = {3};
  Physical Curve(6) = {4};
  Physical Surface(1) = {1};
EndIf
If (planar == 0)
If (quarter == 0)
  Extrude{0, 0, dz}{Surface{1, 2}; Layers{1}; Recombine;}
Else
  Extrude{0, 0, dz}{Surface{1}; Layers{1}; Recombine;}
EndIf
eps = 1e-6;
inner[] = Surface In BoundingBox{-eps, -ri - eps, -eps, ri + eps, ri + eps, dz + eps};
front[] = Surface In BoundingBox{-2, -2, -eps, 2, 2, eps};
back[]  = Surface In BoundingBox{-2, -2, dz - eps, 2, 2, dz + eps};
cutx[]  = Surface In BoundingBox{-eps, -2, -eps, eps, 2, dz + eps};
cuty[]  = Surface In BoundingBox{-2, -eps, -eps, 2, eps, dz + eps};
outer[] = Surface{:};
outer[] -= inner[]; outer[] -= front[]; outer[] -= back[];
outer[] -= cutx[]; outer[] -= cuty[];
Physical Surface(1) = {inner[]};
Physical Surface(2) = {outer[]};
Physical Surface(3) = {front[]};
Physical Surface(4) = {back[]};
Physical Surface(5) = {cutx[]};
If (quarter == 1)
  Physical Surface(6) = {cuty[]};
EndIf
Physical Volume(1) = {Volume{:}};
EndIf
