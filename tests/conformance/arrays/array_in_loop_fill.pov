#version 3.7;
#declare N = 5;
#declare Sq = array[N];
#for (I, 0, N - 1) #declare Sq[I] = I * I; #end
#debug concat("Sq[4] + Sq[3] = ", str(Sq[4] + Sq[3], 0, 0), "\n")
