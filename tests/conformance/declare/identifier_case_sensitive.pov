#version 3.7;
#declare abc = 1;
#declare ABC = 2;
#declare Abc = 3;
#debug concat("abc = ", str(abc, 0, 0), "\n")
#debug concat("ABC = ", str(ABC, 0, 0), "\n")
#debug concat("Abc = ", str(Abc, 0, 0), "\n")
