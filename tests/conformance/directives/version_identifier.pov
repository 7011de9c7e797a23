#version 3.7;
#debug concat("version = ", str(version, 0, 2), "\n")
#version 3.5;
#debug concat("version = ", str(version, 0, 2), "\n")
#version 3.7;
#debug concat("version = ", str(version, 0, 2), "\n")
