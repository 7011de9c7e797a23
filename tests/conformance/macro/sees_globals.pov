#version 3.7;
#declare G = 8;
#macro UseG() (G * 2) #end
#debug concat("UseG() = ", str(UseG(), 0, 0), "\n")
#declare G = 9;
#debug concat("UseG() = ", str(UseG(), 0, 0), "\n")
