#version 3.7;
#debug concat("strlen(\"\\t\\\\\\\"\") = ", str(strlen("\t\\\""), 0, 0), "\n")
