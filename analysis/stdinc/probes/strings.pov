#version 3.7;
// The text that the macros of strings.inc produce.
#include "strings.inc"
#declare C = rgbft <0.25, 0.5, 1, 0.125, 0.0625>;
#debug concat("[", CRGBStr(C, 0, 3), "]\n")
#debug concat("[", CRGBStr(C, 8, 2), "]\n")
#debug concat("[", CRGBStr(C, -6, 1), "]\n")
#debug concat("[", CRGBFTStr(C, 0, 4), "]\n")
#debug concat("[", CRGBFTStr(rgb <1, 2, 3>, 5, 0), "]\n")
#debug concat("[", Str(1/3), "]\n")
#debug concat("[", Str(-12.5), "]\n")
#debug concat("[", Str(1e-7), "]\n")
#debug concat("[", VStr2D(<1/3, -2>), "]\n")
#debug concat("[", VStr(<1/3, -2, 1e6>), "]\n")
#debug concat("[", Vstr2D(<1/3, -2>, 7, 2), "]\n")
#debug concat("[", Vstr(<1/3, -2, 4>, 0, 3), "]\n")
#debug concat("[", Vstr(<1/3, -2, 4>, -8, 1), "]\n")
#debug concat("[", Triangle_Str(<0, 0, 0>, <1, 0, 0>, <0, 1, 0.5>), "]\n")
#debug concat("[", Smooth_Triangle_Str(<0, 0, 0>, y, <1, 0, 0>, <0, 1, 1>, <0, 1, 0.5>, z), "]\n")
#declare Parsed = Parse_String("3 + 4 * 2");
#debug concat("[", str(Parsed, 0, 1), "]\n")
