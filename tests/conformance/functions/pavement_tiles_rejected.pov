#version 3.7;
// A pavement tile has 1 to 6 cells.
#declare P = pigment { pavement number_of_sides 4 number_of_tiles 7 }
#debug "parsed\n"
