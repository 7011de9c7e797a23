#version 3.7;
#macro CountDown(N, Acc)
  #declare Acc = Acc + N;
  #if (N > 0) CountDown(N - 1, Acc) #end
#end
#declare Total = 0;
CountDown(4, Total)
#debug concat("Total = ", str(Total, 0, 0), "\n")
