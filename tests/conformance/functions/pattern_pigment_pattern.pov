#version 3.7;
#declare F = function { pattern { pigment_pattern { rgb <1, 0, 0> } } }
#debug concat("red: ", str(F(0, 0, 0), 0, 6), "\n")
#declare G = function { pattern { pigment_pattern { rgb <0.2, 0.7, 0.4> filter 0.5 } } }
#debug concat("mixed: ", str(G(0, 0, 0), 0, 6), "\n")
#declare H = function { pattern { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb <0, 1, 0>] } } scale 2 } }
#debug concat("scaled: ", str(H(0.5, 0, 0), 0, 6), "\n")
