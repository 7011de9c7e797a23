#version 3.7;
#debug concat("(1<2) = ", str((1<2), 0, 0), "\n")
#debug concat("(2<1) = ", str((2<1), 0, 0), "\n")
#debug concat("(1<=1) = ", str((1<=1), 0, 0), "\n")
#debug concat("(2>=3) = ", str((2>=3), 0, 0), "\n")
#debug concat("(3>2) = ", str((3>2), 0, 0), "\n")
#debug concat("(1=1) = ", str((1=1), 0, 0), "\n")
#debug concat("(1!=1) = ", str((1!=1), 0, 0), "\n")
#debug concat("(2!=1) = ", str((2!=1), 0, 0), "\n")
