#version 3.7;
#debug concat("val(\"123.45\") = ", str(val("123.45"), 0, 6), "\n")
#debug concat("val(\"-1e3\") = ", str(val("-1e3"), 0, 6), "\n")
#debug concat("val(\"  7\") = ", str(val("  7"), 0, 6), "\n")
#debug concat("val(\"0.5\") = ", str(val("0.5"), 0, 6), "\n")
