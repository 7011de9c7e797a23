#version 3.7;
#macro Half(K) #local H = K / 2; H #end
#declare A = Half(8) - Half(2);
#debug concat("A = ", str(A, 0, 1), "\n")
