#version 3.7;
#declare Name = "John";
#declare Name = concat(Name, " Doe");
#debug concat("Name = [", Name, "]\n")
