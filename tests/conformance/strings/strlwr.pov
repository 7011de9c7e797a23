#version 3.7;
#debug concat("strlwr(\"Hello There!\") = [", strlwr("Hello There!"), "]\n")
#debug concat("strlwr(\"ABC123XYZ\") = [", strlwr("ABC123XYZ"), "]\n")
