// The quarter x, y >= 0 of the unit disc, for tests/verification/curved_meshes.py:
// second-order (curved) cells of each kind gmsh makes in 2D.
//
//   gmsh -2 quarter_disc.geo -setnumber quads 0 -o quarter_disc_tri6.msh
//   gmsh -2 quarter_disc.geo -o quarter_disc_quad9.msh
//   gmsh -2 quarter_disc.geo -setnumber incomplete 1 -o quarter_disc_quad8.msh
//
// Physical groups: lines 1 (x = 0), 2 (y = 0), 3 (the arc); surface 1.
SetFactory("OpenCASCADE");
DefineConstant[ quads      = {1, Name "1: quadrilaterals (0: triangles)"},
                order      = {2, Name "geometric order (1, 2)"},
                incomplete = {0, Name "1: serendipity (quad8)"},
                h          = {0.3, Name "element size"} ];
Disk(1) = {0, 0, 0, 1};
Rectangle(2) = {0, 0, 0, 1, 1};
BooleanIntersection(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
MeshSize{ PointsOf{ Surface{3}; } } = h;
If (quads == 1)
  Mesh.RecombineAll = 1;
  Mesh.SubdivisionAlgorithm = 1;
EndIf
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;
eps = 1e-6;
left[]   = Curve In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, eps};
bottom[] = Curve In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, eps};
arc[]    = Boundary{ Surface{3}; };
arc[]   -= {left[], bottom[]};
Physical Curve(1) = {left[]};
Physical Curve(2) = {bottom[]};
Physical Curve(3) = {arc[]};
Physical Surface(1) = {3};
