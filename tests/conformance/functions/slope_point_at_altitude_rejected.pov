#version 3.7;
// slope's point_at form takes no altitude.
#declare P = pigment { slope { point_at <0, 5, 0>, 0, 1 altitude y } }
#debug "parsed\n"
