#version 3.7;
#debug "[\u0041\u0062]\n"
#debug concat("strlen(\"\\u0041\") = ", str(strlen("\u0041"), 0, 0), "\n")
