#version 3.7;
#macro SumArray(Arr)
  #local S = 0;
  #for (I, 0, dimension_size(Arr, 1) - 1) #local S = S + Arr[I]; #end
  S
#end
#declare Data = array[4] {1, 2, 3, 4};
#debug concat("SumArray(Data) = ", str(SumArray(Data), 0, 0), "\n")
