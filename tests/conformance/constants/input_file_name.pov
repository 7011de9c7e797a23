#version 3.7;
#debug concat("input_file_name = [", input_file_name, "]\n")
