#version 3.7;
#debug concat("file_exists(\"file_exists.pov\") = ", str(file_exists("file_exists.pov"), 0, 0), "\n")
#debug concat("file_exists(\"no_such_file.txt\") = ", str(file_exists("no_such_file.txt"), 0, 0), "\n")
#debug concat("file_exists(\"colors.inc\") = ", str(file_exists("colors.inc"), 0, 0), "\n")
