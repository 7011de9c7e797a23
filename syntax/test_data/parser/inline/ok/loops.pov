#while (I < 10) #local I = I + 1; #end
#for (I, 0, 10, 2) sphere { <I, 0, 0>, 1 } #end
