#version 3.7;
#debug concat("clock = ", str(clock, 0, 6), "\n")
#debug concat("clock_on = ", str(clock_on, 0, 6), "\n")
#debug concat("clock_delta = ", str(clock_delta, 0, 6), "\n")
#debug concat("frame_number = ", str(frame_number, 0, 6), "\n")
