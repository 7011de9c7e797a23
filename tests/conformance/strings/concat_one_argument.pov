#version 3.7;
#debug concat("concat(\"solo\") = [", concat("solo"), "]\n")
