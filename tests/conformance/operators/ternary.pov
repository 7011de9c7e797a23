#version 3.7;
#debug concat("(1?2:3) = ", str((1?2:3), 0, 0), "\n")
#debug concat("(0?2:3) = ", str((0?2:3), 0, 0), "\n")
#debug concat("(-1?2:3) = ", str((-1?2:3), 0, 0), "\n")
#debug concat("(1e-11?2:3) = ", str((1e-11?2:3), 0, 0), "\n")
