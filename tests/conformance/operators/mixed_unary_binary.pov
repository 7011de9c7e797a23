#version 3.7;
#debug concat("2*-3 = ", str(2*-3, 0, 3), "\n")
#debug concat("2/-4 = ", str(2/-4, 0, 3), "\n")
#debug concat("-2-3 = ", str(-2-3, 0, 3), "\n")
#debug concat("!0+1 = ", str(!0+1, 0, 3), "\n")
#debug concat("-!0 = ", str(-!0, 0, 3), "\n")
