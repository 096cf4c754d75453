// A C-shaped clip for tests/verification/self_contact.py: a lower arm
// [0, 4] x [0, 0.5] (its bottom fixed), a spine [0, 0.5] x [0.5, 2.5], an
// upper arm [0, 4] x [2.5, 3] and at its free end a tooth 0.5 wide
// hanging from it, its end a half circle of radius 0.25 whose lowest
// point is 0.25 above the lower arm. A load on the upper arm's top above
// the tooth bends the arm until the tooth touches the lower arm: the clip
// closes onto itself. Quadrilaterals of about h.
//   gmsh -2 c_clip.geo -o c_clip.msh
//   gmsh -2 c_clip.geo -setnumber split 1 -o c_clip_split.msh
// Physical groups (lines): 1 the inner boundary (the lower arm's top, the
// spine's inner face, the upper arm's underside, the tooth's inner face
// and rounded end): one self-contact surface; 2 the top above the tooth
// (the load); 3 the bottom (fixed); 5 the rest; surface 1 the clip. With
// split = 1 the tooth's end is 9 and the lower arm's top 10 (the same
// clip as a two-body pair would see it).
DefineConstant[ h = {0.125, Name "element size"},
                split = {0, Name "1: the tooth's end and the arm's top apart"} ];
Mesh.MshFileVersion = 2.2;
Mesh.RecombineAll = 1;
Point(1) = {0, 0, 0, h};      Point(2) = {4, 0, 0, h};
Point(3) = {4, 0.5, 0, h};    Point(4) = {0.5, 0.5, 0, h};
Point(5) = {0.5, 2.5, 0, h};  Point(6) = {3.5, 2.5, 0, h};
Point(7) = {3.5, 1, 0, h};    Point(8) = {3.75, 0.75, 0, h};
Point(9) = {4, 1, 0, h};      Point(10) = {4, 3, 0, h};
Point(11) = {3.5, 3, 0, h};   Point(12) = {0, 3, 0, h};
Point(13) = {3.75, 1, 0, h};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};
Line(4) = {4, 5};  Line(5) = {5, 6};  Line(6) = {6, 7};
Circle(7) = {7, 13, 8}; Circle(8) = {8, 13, 9};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12};
Line(12) = {12, 1};
Curve Loop(1) = {1 : 12};
Plane Surface(1) = {1};
If (split == 0)
  Physical Curve(1) = {3, 4, 5, 6, 7, 8};
Else
  Physical Curve(1) = {4, 5, 6};
  Physical Curve(9) = {7, 8};
  Physical Curve(10) = {3};
EndIf
Physical Curve(2) = {10};
Physical Curve(3) = {1};
Physical Curve(5) = {2, 9, 11, 12};
Physical Surface(1) = {1};
