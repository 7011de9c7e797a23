#version 3.7;
#debug concat("asc(\"ABC\") = ", str(asc("ABC"), 0, 0), "\n")
#debug concat("asc(\"a\") = ", str(asc("a"), 0, 0), "\n")
#debug concat("asc(\"0\") = ", str(asc("0"), 0, 0), "\n")
#debug concat("asc(\" \") = ", str(asc(" "), 0, 0), "\n")
#debug concat("asc(\"~\") = ", str(asc("~"), 0, 0), "\n")
