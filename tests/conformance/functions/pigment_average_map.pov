#version 3.7;
#declare P = pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1> filter 0.4] } }
#declare F = function { pigment { P } }
#declare C = F(0.3, 0.4, 0.5);
#debug concat("weighted: ", vstr(5, C, ", ", 0, 4), "\n")
#declare White = pigment { rgb 1 }
#declare Q = pigment { average pigment_map { [gradient x] [White] } scale 2 }
#declare G = function { pigment { Q } }
#declare D = G(0.5, 0, 0);
#debug concat("unweighted: ", vstr(3, D, ", ", 0, 4), "\n")
