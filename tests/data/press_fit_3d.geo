// A 3D press fit for tests/verification/curved_meshes.py: two spherical shells in contact on
// the sphere r = b, the inner one (a to b) loaded by a pressure on r = a,
// the outer one (b to c) free outside; the octant x, y, z >= 0, each shell
// meshed on its own (non-matching on r = b), tetrahedra split into
// hexahedra by gmsh, second-order (curved hex27):
//
//   gmsh -3 press_fit_3d.geo -o press_fit_3d_hex27.msh
//
// Physical groups: surfaces 1 (r = a), 2 (r = b, inner shell), 3 (r = b,
// outer shell), 4 (r = c), 5 (x = 0), 6 (y = 0), 7 (z = 0); volumes 1
// (inner shell), 2 (outer shell).
SetFactory("OpenCASCADE");
DefineConstant[ a     = {1,    Name "inner radius"},
                b     = {1.5,  Name "contact radius"},
                c     = {2,    Name "outer radius"},
                hi    = {0.4,  Name "element size, inner shell"},
                ho    = {0.6,  Name "element size, outer shell"},
                ni    = {6,    Name "nodes on an arc of r = b, inner shell"},
                no    = {4,    Name "nodes on an arc of r = b, outer shell"},
                hex   = {1,    Name "1: hexahedra (0: tetrahedra)"},
                order = {2,    Name "geometric order (1, 2)"} ];
Sphere(1) = {0, 0, 0, b};
Sphere(2) = {0, 0, 0, a};
Sphere(3) = {0, 0, 0, c};
Sphere(4) = {0, 0, 0, b};
Box(5) = {0, 0, 0, c + 1, c + 1, c + 1};
Box(6) = {0, 0, 0, c + 1, c + 1, c + 1};
BooleanDifference(7) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
BooleanDifference(8) = { Volume{3}; Delete; }{ Volume{4}; Delete; };
BooleanIntersection(9) = { Volume{7}; Delete; }{ Volume{5}; Delete; };
BooleanIntersection(10) = { Volume{8}; Delete; }{ Volume{6}; Delete; };
MeshSize{ PointsOf{ Volume{9}; } } = hi;
MeshSize{ PointsOf{ Volume{10}; } } = ho;
If (hex == 1)
  Mesh.SubdivisionAlgorithm = 2;
EndIf
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;
eps = 1e-6;
R = c + 1;
x0[] = Surface In BoundingBox{-eps, -eps, -eps, eps, R, R};
y0[] = Surface In BoundingBox{-eps, -eps, -eps, R, eps, R};
z0[] = Surface In BoundingBox{-eps, -eps, -eps, R, R, eps};
inner[] = Abs(Boundary{ Volume{9}; });
inner[] -= {x0[], y0[], z0[]};
outer[] = Abs(Boundary{ Volume{10}; });
outer[] -= {x0[], y0[], z0[]};
sa[] = Surface In BoundingBox{-eps, -eps, -eps, a + eps, a + eps, a + eps};
sb_outer[] = Surface In BoundingBox{-eps, -eps, -eps, b + eps, b + eps, b + eps};
sb_outer[] -= {inner[], x0[], y0[], z0[]};
sb_inner[] = inner[];
sb_inner[] -= {sa[]};
sc[] = outer[];
sc[] -= {sb_outer[]};
// The arcs of r = b: 6 and 4 nodes (5 and 3 segments before the
// subdivision halves them), so the two meshes do not match there.
Transfinite Curve{Abs(Boundary{ Surface{sb_inner[]}; })} = ni;
Transfinite Curve{Abs(Boundary{ Surface{sb_outer[]}; })} = no;
Physical Surface(1) = {sa[]};
Physical Surface(2) = {sb_inner[]};
Physical Surface(3) = {sb_outer[]};
Physical Surface(4) = {sc[]};
Physical Surface(5) = {x0[]};
Physical Surface(6) = {y0[]};
Physical Surface(7) = {z0[]};
Physical Volume(1) = {9};
Physical Volume(2) = {10};
