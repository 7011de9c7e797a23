#version 3.7;
#local Saved = version;
#version 3.1;
#debug concat("version = ", str(version, 0, 2), "\n")
#version Saved;
#debug concat("version = ", str(version, 0, 2), "\n")
