// The octant x, y, z >= 0 of the unit ball, for tests/verification/curved_meshes.py:
// second-order (curved) cells of each kind gmsh makes in 3D.
//
//   gmsh -3 ball_octant.geo -setnumber hex 0 -o ball_octant_tet10.msh
//   gmsh -3 ball_octant.geo -setnumber h 1 -o ball_octant_hex27.msh
//   gmsh -3 ball_octant.geo -setnumber h 1 -setnumber incomplete 1 \
//        -o ball_octant_hex20.msh
//
// Physical groups: surfaces 1 (x = 0), 2 (y = 0), 3 (z = 0), 4 (the
// sphere); volume 1.
SetFactory("OpenCASCADE");
DefineConstant[ hex        = {1, Name "1: hexahedra (0: tetrahedra)"},
                order      = {2, Name "geometric order (1, 2)"},
                incomplete = {0, Name "1: serendipity (hex20)"},
                h          = {0.5, Name "element size"} ];
Sphere(1) = {0, 0, 0, 1};
Box(2) = {0, 0, 0, 1, 1, 1};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
MeshSize{ PointsOf{ Volume{3}; } } = h;
If (hex == 1)
  Mesh.SubdivisionAlgorithm = 2;
EndIf
Mesh.ElementOrder = order;
Mesh.SecondOrderIncomplete = incomplete;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;
eps = 1e-6;
sx[] = Surface In BoundingBox{-eps, -eps, -eps, eps, 1 + eps, 1 + eps};
sy[] = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, eps, 1 + eps};
sz[] = Surface In BoundingBox{-eps, -eps, -eps, 1 + eps, 1 + eps, eps};
sphere[] = Boundary{ Volume{3}; };
sphere[] -= {sx[], sy[], sz[]};
Physical Surface(1) = {sx[]};
Physical Surface(2) = {sy[]};
Physical Surface(3) = {sz[]};
Physical Surface(4) = {sphere[]};
Physical Volume(1) = {3};
