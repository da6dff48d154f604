// Bad geometry for tests/CMakeLists.txt (bad_input_geometry_syntax): Gmsh cannot run this
// script (the brace of Point(3) is not closed). Must fail naming the file.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {0, 1, 0;
