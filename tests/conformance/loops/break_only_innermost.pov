#version 3.7;
#for (I, 1, 3)
  #for (J, 1, 3)
    #if (J = 2) #break #end
    #debug concat(str(I, 0, 0), ":", str(J, 0, 0), " ")
  #end
#end
#debug "\n"
