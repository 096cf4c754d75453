// Hertz 3D peer benchmark: the quarter x, y >= 0 of the lower half of a
// sphere of radius R = 10, centre (0, 0, R), lowest point at the origin on
// the rigid plane z = 0. Tetrahedra with a fine zone around the contact
// point, split into hexahedra by gmsh's subdivision (hex = 1, the
// default: first-order hexahedra, what GetFEM's Q1 nodal contact uses in
// the benchmark and what tribos could read), or left as tetrahedra
// (-setnumber hex 0); -setnumber order 2 for curved second-order cells
// (tet10, or hex27 with hex = 1).
//
//   gmsh -3 hertz_3d.geo -o hertz_3d_20k.msh     (19911 dofs, Q1)
//
// Physical groups: 10 curved surface (contact), 11 flat top z = R (load),
// 12 symmetry plane x = 0, 13 symmetry plane y = 0, 1 the body.
SetFactory("OpenCASCADE");
DefineConstant[ R     = {10.0, Name "radius"},
                hf    = {0.25, Name "element size in the fine zone"},
                rf    = {0.14, Name "fine zone radius / R"},
                hc    = {0.2,  Name "largest element size / R"},
                grow  = {2.0,  Name "size grows from hf to hc R over grow rf R"},
                order = {1,    Name "geometric order of the elements (1, 2)"},
                hex   = {1,    Name "1: split into hexahedra (0: tetrahedra)"} ];

Sphere(1) = {0, 0, R, R};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Point(100) = {0, 0, 0};            // contact point, for the size field
eps = 1e-6 * R;
sx[] = Surface In BoundingBox{-eps, -eps, -eps, eps, R + eps, R + eps};
sy[] = Surface In BoundingBox{-eps, -eps, -eps, R + eps, eps, R + eps};
st[] = Surface In BoundingBox{-eps, -eps, R - eps, R + eps, R + eps, R + eps};
all[] = Boundary{ Volume{3}; };
sc[] = all[];
sc[] -= {sx[], sy[], st[]};

Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hc * R;
Field[2].DistMin = rf * R;
Field[2].DistMax = (1 + grow) * rf * R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Mesh.Algorithm = 6;
Mesh.Algorithm3D = 1;          // Delaunay
Mesh.Optimize = 1;
If (hex == 1)
  Mesh.SubdivisionAlgorithm = 2; // every tetrahedron into 4 hexahedra
EndIf
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;

Physical Surface(10) = {sc[]};
Physical Surface(11) = {st[]};
Physical Surface(12) = {sx[]};
Physical Surface(13) = {sy[]};
Physical Volume(1) = {3};
