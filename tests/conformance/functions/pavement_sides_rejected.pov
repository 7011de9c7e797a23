#version 3.7;
// Pavement cells have 3, 4 or 6 sides.
#declare P = pigment { pavement number_of_sides 5 }
#debug "parsed\n"
