#version 3.7;
#include "consts.inc"
#debug concat("e = ", str(e, 0, 6), "\n")
#debug concat("Water_Ior = ", str(Water_Ior, 0, 6), "\n")
#debug concat("Diamond_Ior = ", str(Diamond_Ior, 0, 6), "\n")
#debug concat("Diamond_Dispersion = ", str(Diamond_Dispersion, 0, 6), "\n")
#debug concat("FoV_45 = ", str(FoV_45, 0, 6), "\n")
#debug concat("Sphere_Map = ", str(Sphere_Map, 0, 6), "\n")
#debug concat("RAYLEIGH_SCATTERING = ", str(RAYLEIGH_SCATTERING, 0, 6), "\n")
#debug concat("xy = <", vstr(3, xy, ", ", 0, 0), ">\n")
