#version 3.7;
// A slope with neither a direction nor an altitude is refused.
#declare P = pigment { slope { <0, 0, 0> altitude 0 } }
#debug "parsed\n"
