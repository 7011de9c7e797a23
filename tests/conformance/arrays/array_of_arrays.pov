#version 3.7;
#declare Inner = array[2] {7, 8};
#declare Outer = array[1] {Inner};
#debug concat("Outer[0][1] = ", str(Outer[0][1], 0, 0), "\n")
