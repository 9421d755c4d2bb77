// Quarter of a tube (x >= 0, y >= 0) meshed with quadrilaterals for tubeform.
// Parameters can be changed on the command line, e.g.
//   gmsh -2 -format msh41 -setnumber ro 17.5 -setnumber t 1.5 \
//        -setnumber nt 4 -setnumber ntheta 48 meshes/quarter_tube.geo -o tube.msh
// Physical curves inner, outer, x0 (on the y axis), y0 (on the x axis) are the
// boundary sets tubeform needs.
DefineConstant[ ro = 17.5, t = 1.5, nt = 4, ntheta = 48 ];
ri = ro - t;

Point(1) = {0, 0, 0};
Point(2) = {ri, 0, 0};
Point(3) = {ro, 0, 0};
Point(4) = {0, ro, 0};
Point(5) = {0, ri, 0};

Line(1) = {2, 3};         // y = 0
Circle(2) = {3, 1, 4};    // outer
Line(3) = {4, 5};         // x = 0
Circle(4) = {5, 1, 2};    // inner
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = nt + 1;
Transfinite Curve{2, 4} = ntheta + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve("y0") = {1};
Physical Curve("outer") = {2};
Physical Curve("x0") = {3};
Physical Curve("inner") = {4};
Physical Surface("tube") = {1};
