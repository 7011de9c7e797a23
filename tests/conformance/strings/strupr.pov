#version 3.7;
#debug concat("strupr(\"Hello There!\") = [", strupr("Hello There!"), "]\n")
#debug concat("strupr(\"abc123xyz\") = [", strupr("abc123xyz"), "]\n")
