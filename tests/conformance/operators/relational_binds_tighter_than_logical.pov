#version 3.7;
#debug concat("(1<2&2<3) = ", str((1<2&2<3), 0, 0), "\n")
#debug concat("(1>2|2>3) = ", str((1>2|2>3), 0, 0), "\n")
#debug concat("(1=1&0) = ", str((1=1&0), 0, 0), "\n")
