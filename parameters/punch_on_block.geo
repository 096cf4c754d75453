// A cylindrical punch (radius 0.3, height 0.3) on a block 2 x 1 x 0.4, each
// meshed with tetrahedra on its own (the contact interface is non-matching),
// half model y >= 0:  gmsh -3 punch_on_block.geo -o punch_on_block.msh
// Physical groups: volumes 1 block, 2 punch; surfaces 1 block bottom, 2 block
// top, 3 punch bottom, 4 punch top, 5 symmetry plane y = 0 (both bodies).
SetFactory("OpenCASCADE");
DefineConstant[ h_block = {0.1, Name "element size of the block"},
                h_punch = {0.06, Name "element size of the punch"} ];
Box(1) = {-1, 0, -0.4, 2, 1, 0.4};
Cylinder(2) = {0, 0, 0, 0, 0, 0.3, 0.3};
Box(3) = {-1, 0, -1, 2, 1, 2};
BooleanIntersection(4) = { Volume{2}; Delete; }{ Volume{3}; Delete; };
eps = 1e-6;
bottom[] = Surface In BoundingBox{-1-eps, -eps, -0.4-eps, 1+eps, 1+eps, -0.4+eps};
top[]    = Surface In BoundingBox{-1-eps, -eps, -eps, 1+eps, 1+eps, eps};
sym_b[]  = Surface In BoundingBox{-1-eps, -eps, -0.4-eps, 1+eps, eps, eps};
p_bottom[] = Surface In BoundingBox{-0.3-eps, -eps, -eps, 0.3+eps, 0.3+eps, eps};
p_top[]    = Surface In BoundingBox{-0.3-eps, -eps, 0.3-eps, 0.3+eps, 0.3+eps, 0.3+eps};
sym_p[]    = Surface In BoundingBox{-0.3-eps, -eps, -eps, 0.3+eps, eps, 0.3+eps};
top[] -= {p_bottom[]};
MeshSize{ PointsOf{ Volume{1}; } } = h_block;
MeshSize{ PointsOf{ Volume{4}; } } = h_punch;
Mesh.MshFileVersion = 2.2;
Physical Volume(1) = {1};
Physical Volume(2) = {4};
Physical Surface(1) = {bottom[]};
Physical Surface(2) = {top[]};
Physical Surface(3) = {p_bottom[]};
Physical Surface(4) = {p_top[]};
Physical Surface(5) = {sym_b[], sym_p[]};
