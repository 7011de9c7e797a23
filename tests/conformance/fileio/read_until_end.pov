#version 3.7;
#fopen F "numbers.txt" read
#declare Sum = 0;
#declare Count = 0;
#while (defined(F))
  #read (F, V)
  #if (defined(F))
    #declare Sum = Sum + V;
    #declare Count = Count + 1;
  #end
#end
#debug concat("Count = ", str(Count, 0, 0), "\n")
#debug concat("Sum = ", str(Sum, 0, 3), "\n")
