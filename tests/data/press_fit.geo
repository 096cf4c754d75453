// A press fit for tests/verification/curved_meshes.py: two rings in contact on the
// circle r = b, the inner one (a to b) loaded by a pressure on r = a, the
// outer one (b to c) free outside; the quarter x, y >= 0, each ring meshed
// on its own (non-matching on r = b: 14 and 9 segments before gmsh's
// subdivision of the quadrilaterals), second-order (curved):
//
//   gmsh -2 press_fit.geo -o press_fit_quad9.msh
//   gmsh -2 press_fit.geo -setnumber quads 0 -o press_fit_tri6.msh
//
// Physical groups: lines 1 (r = a), 2 (r = b, inner ring), 3 (r = b, outer
// ring), 4 (r = c), 5 (x = 0, both), 6 (y = 0, both); surfaces 1 (inner
// ring), 2 (outer ring).
SetFactory("OpenCASCADE");
DefineConstant[ a     = {1,    Name "inner radius"},
                b     = {1.5,  Name "contact radius"},
                c     = {2,    Name "outer radius"},
                hi    = {0.12, Name "element size, inner ring"},
                ho    = {0.17, Name "element size, outer ring"},
                quads = {1,    Name "1: quadrilaterals (0: triangles)"},
                order = {2,    Name "geometric order (1, 2)"} ];
Disk(1) = {0, 0, 0, b};
Disk(2) = {0, 0, 0, a};
Disk(3) = {0, 0, 0, c};
Disk(4) = {0, 0, 0, b};
Rectangle(5) = {0, 0, 0, c + 1, c + 1};
Rectangle(6) = {0, 0, 0, c + 1, c + 1};
BooleanDifference(7) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
BooleanDifference(8) = { Surface{3}; Delete; }{ Surface{4}; Delete; };
BooleanIntersection(9) = { Surface{7}; Delete; }{ Surface{5}; Delete; };
BooleanIntersection(10) = { Surface{8}; Delete; }{ Surface{6}; Delete; };
MeshSize{ PointsOf{ Surface{9}; } } = hi;
MeshSize{ PointsOf{ Surface{10}; } } = ho;
If (quads == 1)
  Mesh.RecombineAll = 1;
  Mesh.SubdivisionAlgorithm = 1;
EndIf
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;
eps = 1e-6;
inner[] = Abs(Boundary{ Surface{9}; });
outer[] = Abs(Boundary{ Surface{10}; });
x0[] = Curve In BoundingBox{-eps, -eps, -eps, eps, c + eps, eps};
y0[] = Curve In BoundingBox{-eps, -eps, -eps, c + eps, eps, eps};
arc_a[] = Curve In BoundingBox{-eps, -eps, -eps, a + eps, a + eps, eps};
arc_b_inner[] = inner[];
arc_b_inner[] -= {x0[], y0[], arc_a[]};
arc_b_outer[] = Curve In BoundingBox{-eps, -eps, -eps, b + eps, b + eps, eps};
arc_b_outer[] -= {inner[]};
arc_c[] = outer[];
arc_c[] -= {x0[], y0[], arc_b_outer[]};
Transfinite Curve{arc_b_inner[]} = 15;
Transfinite Curve{arc_b_outer[]} = 10;
Physical Curve(1) = {arc_a[]};
Physical Curve(2) = {arc_b_inner[]};
Physical Curve(3) = {arc_b_outer[]};
Physical Curve(4) = {arc_c[]};
Physical Curve(5) = {x0[]};
Physical Curve(6) = {y0[]};
Physical Surface(1) = {9};
Physical Surface(2) = {10};
