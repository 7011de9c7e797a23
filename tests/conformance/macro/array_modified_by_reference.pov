#version 3.7;
#macro Fill(Arr) #declare Arr[0] = 42; #end
#declare Data = array[2] {1, 2};
Fill(Data)
#debug concat("Data[0] = ", str(Data[0], 0, 0), "\n")
