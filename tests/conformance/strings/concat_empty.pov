#version 3.7;
#debug concat("concat(\"\", \"x\", \"\") = [", concat("", "x", ""), "]\n")
#debug concat("concat(\"\", \"\") = [", concat("", ""), "]\n")
