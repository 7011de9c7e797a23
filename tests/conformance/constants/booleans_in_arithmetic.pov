#version 3.7;
#debug concat("true+true = ", str(true+true, 0, 0), "\n")
#debug concat("on*5 = ", str(on*5, 0, 0), "\n")
#debug concat("yes-no = ", str(yes-no, 0, 0), "\n")
#debug concat("(true=on) = ", str((true=on), 0, 0), "\n")
