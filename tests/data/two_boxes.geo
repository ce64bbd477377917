// Two boxes meshed separately that interpenetrate (no fragmentation): the kind of
// assembly whose parts intersect that has no visibility order. Only the volume cells are
// saved (physical group), so the legacy .vtk holds tetrahedra only.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0.6, 0.3, 0.2, 1, 1, 1};
Physical Volume(1) = {1, 2};
Mesh.MeshSizeMax = 0.35;
