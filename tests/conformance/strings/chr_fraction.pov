#version 3.7;
#debug concat("chr(65.9) = [", chr(65.9), "]\n")
#debug concat("concat(chr(72), chr(105)) = [", concat(chr(72), chr(105)), "]\n")
