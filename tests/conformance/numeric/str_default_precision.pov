#version 3.7;
#debug concat("1/3 = ", str(1/3, 0, -1), "\n")
#debug concat("2 = ", str(2, 0, -1), "\n")
#debug concat("-1e-7 = ", str(-1e-7, 0, -1), "\n")
#debug concat("123456.7891 = ", str(123456.7891, 0, -1), "\n")
