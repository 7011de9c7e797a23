#version 3.7;
#declare D = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#for (I, 0, 1)
  #for (J, 0, 2) #debug concat(str(D[I][J], 0, 0), " ") #end
  #debug "\n"
#end
