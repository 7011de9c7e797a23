#version 3.7;
#fopen F "values.txt" read
#declare Name = 5;
#debug "before\n"
#read (F, Name)
