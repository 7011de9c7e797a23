#version 3.7;
// Pavement values through pigment functions: squares, triangles and hexagons, one
// polyform of each, with a corner of each kind near the points.
#declare S = function { pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 color_map { [0 rgb 0] [1 rgb 1] } } }
#declare T = function { pigment { pavement number_of_tiles 6 pattern 9 color_map { [0 rgb 0] [1 rgb 1] } } }
#declare H = function { pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 3 color_map { [0 rgb 0] [1 rgb 1] } } }
#debug concat(str(S(1.37, 0, 2.11).red, 0, 6), " ", str(S(-3.9, 5, 0.45).red, 0, 6), "\n")
#debug concat(str(T(0.61, 0, 1.3).red, 0, 6), " ", str(T(4.2, 0, -2.75).red, 0, 6), "\n")
#debug concat(str(H(2.2, 0, 1.1).red, 0, 6), " ", str(H(-1.35, 0, 3.3).red, 0, 6), "\n")
