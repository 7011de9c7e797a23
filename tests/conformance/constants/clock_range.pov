#version 3.7;
#debug concat("initial_clock = ", str(initial_clock, 0, 6), "\n")
#debug concat("final_clock = ", str(final_clock, 0, 6), "\n")
#debug concat("initial_frame = ", str(initial_frame, 0, 6), "\n")
#debug concat("final_frame = ", str(final_frame, 0, 6), "\n")
