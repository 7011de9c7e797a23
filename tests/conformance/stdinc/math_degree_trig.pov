#version 3.7;
#include "math.inc"
#debug concat("sind(30) = ", str(sind(30), 0, 9), "\n")
#debug concat("cosd(60) = ", str(cosd(60), 0, 9), "\n")
#debug concat("tand(45) = ", str(tand(45), 0, 9), "\n")
#debug concat("asind(0.5) = ", str(asind(0.5), 0, 9), "\n")
#debug concat("acosd(0.5) = ", str(acosd(0.5), 0, 9), "\n")
#debug concat("atand(1) = ", str(atand(1), 0, 9), "\n")
#debug concat("atan2d(1, -1) = ", str(atan2d(1, -1), 0, 9), "\n")
