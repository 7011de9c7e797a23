#version 3.7;
#debug concat("true = ", str(true, 0, 0), "\n")
#debug concat("false = ", str(false, 0, 0), "\n")
#debug concat("on = ", str(on, 0, 0), "\n")
#debug concat("off = ", str(off, 0, 0), "\n")
#debug concat("yes = ", str(yes, 0, 0), "\n")
#debug concat("no = ", str(no, 0, 0), "\n")
