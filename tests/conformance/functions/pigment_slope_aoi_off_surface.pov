#version 3.7;
// Off a surface slope and aoi are 0 before the wave shaping, in a pigment function.
#declare S = function { pigment { slope { y, 0.2, 0.7 altitude y, -1, 1 } phase 0.3 color_map { [0 rgb 0] [1 rgb 1] } } }
#declare A = function { pigment { aoi frequency 2 phase 0.25 color_map { [0 rgb 0] [1 rgb 1] } } }
#declare P = function { pigment { slope { point_at <1, 2, 3> } color_map { [0 rgb 0.5] [1 rgb 1] } } }
#debug concat(str(S(0, 0.5, 0).red, 0, 6), " ", str(A(1, 2, 3).red, 0, 6), " ", str(P(0, 0, 0).red, 0, 6), "\n")
