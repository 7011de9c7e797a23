#version 3.7;
#debug concat("-<1,2,3>.y = ", str(-<1,2,3>.y, 0, 3), "\n")
#debug concat("-x.x = ", str(-x.x, 0, 3), "\n")
#debug concat("-(<1,2,3>.z) = ", str(-(<1,2,3>.z), 0, 3), "\n")
#debug concat("2*-<1,2,3>.y = ", str(2*-<1,2,3>.y, 0, 3), "\n")
