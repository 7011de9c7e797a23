#version 3.7;
#debug concat("val(\"abc\") = ", str(val("abc"), 0, 6), "\n")
#debug concat("val(\"3x\") = ", str(val("3x"), 0, 6), "\n")
#debug concat("val(\"\") = ", str(val(""), 0, 6), "\n")
#debug concat("val(\"1e\") = ", str(val("1e"), 0, 6), "\n")
#debug concat("val(\"+4\") = ", str(val("+4"), 0, 6), "\n")
