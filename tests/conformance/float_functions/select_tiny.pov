#version 3.7;
#debug concat("select(1e-11, 1, 2, 3) = ", str(select(1e-11, 1, 2, 3), 0, 0), "\n")
#debug concat("select(-1e-11, 1, 2, 3) = ", str(select(-1e-11, 1, 2, 3), 0, 0), "\n")
#debug concat("select(-0, 1, 2, 3) = ", str(select(-0, 1, 2, 3), 0, 0), "\n")
