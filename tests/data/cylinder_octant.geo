// The paper's cylinder (radius 6.35 mm, height 2 r) as its 1/8 model x, y,
// z >= 0 (axis z), meshed with second-order (curved) tetrahedra or
// hexahedra (each tetrahedron split into four), for
// tests/verification/curved_meshes.py:
//
//   gmsh -3 cylinder_octant.geo -o cylinder_octant_tet10.msh
//   gmsh -3 cylinder_octant.geo -setnumber hex 1 -setnumber h 6.35 \
//        -o cylinder_octant_hex27.msh
//
// Physical groups: surfaces 1 (x = 0), 2 (y = 0), 3 (z = 0), 4 (the top z
// = r, under the plate), 5 (the curved side); volume 1.
SetFactory("OpenCASCADE");
DefineConstant[ r     = {6.35, Name "radius"},
                h     = {2.5,  Name "element size"},
                order = {2,    Name "geometric order (1, 2)"},
                hex   = {0,    Name "1: hexahedra (0: tetrahedra)"} ];
Cylinder(1) = {0, 0, 0, 0, 0, r, r};
Box(2) = {0, 0, 0, r, r, r};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
MeshSize{ PointsOf{ Volume{3}; } } = h;
If (hex == 1)
  Mesh.SubdivisionAlgorithm = 2;
EndIf
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;
eps = 1e-6;
sx[] = Surface In BoundingBox{-eps, -eps, -eps, eps, r + eps, r + eps};
sy[] = Surface In BoundingBox{-eps, -eps, -eps, r + eps, eps, r + eps};
sz[] = Surface In BoundingBox{-eps, -eps, -eps, r + eps, r + eps, eps};
top[] = Surface In BoundingBox{-eps, -eps, r - eps, r + eps, r + eps, r + eps};
side[] = Boundary{ Volume{3}; };
side[] -= {sx[], sy[], sz[], top[]};
Physical Surface(1) = {sx[]};
Physical Surface(2) = {sy[]};
Physical Surface(3) = {sz[]};
Physical Surface(4) = {top[]};
Physical Surface(5) = {side[]};
Physical Volume(1) = {3};
