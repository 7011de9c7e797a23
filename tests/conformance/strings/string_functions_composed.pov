#version 3.7;
#debug concat("strupr(substr(concat(\"hello\", \" \", \"world\"), 7, 5)) = [", strupr(substr(concat("hello", " ", "world"), 7, 5)), "]\n")
