#version 3.7;
#include "strings.inc"
#debug concat("CRGBStr(rgb <1, 0.5, 0.25>, 0, 2) = [", CRGBStr(rgb <1, 0.5, 0.25>, 0, 2), "]\n")
#debug concat("FT = [", CRGBFTStr(rgbft <1, 0.5, 0.25, 0.1, 0.2>, 0, 1), "]\n")
