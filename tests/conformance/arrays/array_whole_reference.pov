#version 3.7;
#declare MyArray = array[10];
#declare YourArray = MyArray;
#debug concat("dimension_size(YourArray, 1) = ", str(dimension_size(YourArray, 1), 0, 0), "\n")
