// A .geo file with a syntax error: meshing must fail with one clear message naming the file.
Point(1) = {0, 0, 0
