#version 3.7;
#declare A_very_long_identifier_name_of_forty_chars = 9;
#debug concat("A_very_long_identifier_name_of_forty_chars = ", str(A_very_long_identifier_name_of_forty_chars, 0, 0), "\n")
