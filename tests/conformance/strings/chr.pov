#version 3.7;
#debug concat("chr(65) = [", chr(65), "]\n")
#debug concat("chr(97) = [", chr(97), "]\n")
#debug concat("chr(48) = [", chr(48), "]\n")
#debug concat("chr(32) = [", chr(32), "]\n")
#debug concat("chr(126) = [", chr(126), "]\n")
