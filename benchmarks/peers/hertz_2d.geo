// Hertz 2D (plane strain) peer benchmark: the quarter x >= 0 of the lower
// half of a cylinder of radius R = 1, centre (0, R), lowest point at the
// origin on the rigid plane y = 0. All-quadrilateral first-order mesh with
// a fine zone around the contact point.
//
//   gmsh -2 -setnumber hf 0.00775 hertz_2d.geo -o hertz_2d_13k.msh  (13790 dofs)
//   gmsh -2 -setnumber hf 0.00338 hertz_2d.geo -o hertz_2d_49k.msh  (49242 dofs)
//   gmsh -2 -setnumber hf 0.0078 -setnumber quads 0 hertz_2d.geo \
//        -o ../../tests/data/hertz_2d_tri.msh  (triangles, 3578 dofs)
//   gmsh -2 -setnumber hf 0.0078 -setnumber quads 0 -setnumber order 2 \
//        hertz_2d.geo -o ../../tests/data/hertz_2d_tri6.msh  (curved six-node
//        triangles, P2)
//
// (hf is the size before the final subdivision: the quadrilaterals along
// the contact are hf / 2, 0.0039 and 0.0017, i.e. a / 28 and a / 64 for
// the Hertz half-width a = 0.1076 of the benchmark load.)
//
// Physical groups (tribos: boundary ids / body id; GetFEM: regions):
//   10 curved surface (contact), 11 flat top y = R (load),
//   12 symmetry line x = 0 (u_x = 0), 1 the body.
DefineConstant[ R  = {1.0,  Name "radius"},
                hf = {0.004, Name "element size in the fine zone"},
                rf = {0.25, Name "fine zone radius / R"},
                hc = {0.05, Name "largest element size / R"},
                quads = {1, Name "1: quadrilaterals (0: triangles)"},
                order = {1, Name "geometric order of the elements (1, 2)"} ];

Point(1) = {0, 0, 0};      // contact point
Point(2) = {0, R, 0};      // centre (and top of the symmetry line)
Point(3) = {R, R, 0};      // end of the flat top
Line(1) = {1, 2};          // symmetry line x = 0
Line(2) = {2, 3};          // flat top
Circle(3) = {3, 2, 1};     // curved surface, from the top down to the origin
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// element size: hf within rf R of the contact point, growing linearly to
// hc at 2.5 rf R
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hf;
Field[2].SizeMax = hc * R;
Field[2].DistMin = rf * R;
Field[2].DistMax = 2.5 * rf * R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// all quadrilaterals (or all triangles), first order (or second: curved)
Mesh.Algorithm = 6;             // frontal-Delaunay (8, "for quads", crashes
                                // Debian's gmsh 4.8.4), then recombined
If (quads == 1)
  Mesh.RecombineAll = 1;
  Mesh.RecombinationAlgorithm = 1; // blossom
  Mesh.SubdivisionAlgorithm = 1;   // split what is left into quads (halves h)
EndIf
Mesh.ElementOrder = order;
Mesh.HighOrderOptimize = 0;
Mesh.MshFileVersion = 2.2;

Physical Curve(10) = {3};
Physical Curve(11) = {2};
Physical Curve(12) = {1};
Physical Surface(1) = {1};
