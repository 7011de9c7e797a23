#version 3.7;
#debug concat("strlen(\"\") = ", str(strlen(""), 0, 0), "\n")
#debug concat("strlen(\"a\") = ", str(strlen("a"), 0, 0), "\n")
#debug concat("strlen(\"hello world\") = ", str(strlen("hello world"), 0, 0), "\n")
#debug concat("strlen(\"a\\nb\") = ", str(strlen("a\nb"), 0, 0), "\n")
#debug concat("strlen(\"\\\\\") = ", str(strlen("\\"), 0, 0), "\n")
