#version 3.7;
#debug concat("(<1,2,3>*2).z = ", str((<1,2,3>*2).z, 0, 3), "\n")
#debug concat("(x+y).y = ", str((x+y).y, 0, 3), "\n")
#debug concat("(<1,2,3>+1).x = ", str((<1,2,3>+1).x, 0, 3), "\n")
