#version 3.7;
#fopen F "values.txt" read
#read (F, Name, Number, Vec)
#debug concat("Name = [", Name, "]\n")
#debug concat("Number = ", str(Number, 0, 3), "\n")
#debug concat("Vec = <", vstr(3, Vec, ", ", 0, 2), ">\n")
