#version 3.7;
#debug concat("1e308*10 = ", str(1e308*10, 0, 3), "\n")
#debug concat("-1e308*10 = ", str(-1e308*10, 0, 3), "\n")
#debug concat("1e308*10-1e308*10 = ", str(1e308*10-1e308*10, 0, 3), "\n")
