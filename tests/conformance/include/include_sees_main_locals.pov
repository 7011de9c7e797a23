#version 3.7;
#local Seen = 5;
#include "include_reads.inc"
#debug concat("Read_Back = ", str(Read_Back, 0, 0), "\n")
