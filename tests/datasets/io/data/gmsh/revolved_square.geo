// A square with one side on the y axis, meshed with triangles and revolved about that axis
// in layers: triangles away from the axis sweep into prisms (wedges), triangles with one
// vertex on the axis into pyramids, triangles with a side on it into tetrahedra. gmsh
// writes the vertices, lines, triangles and quads of the model into the file beside them.
h = 0.4;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude {{0, 1, 0}, {0, 0, 0}, Pi / 3} { Surface{1}; Layers{2}; Recombine; }
