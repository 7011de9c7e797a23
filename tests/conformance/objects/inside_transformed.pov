#version 3.7;
#declare S = sphere { 0, 1 scale <3, 1, 1> translate 5*x }
#debug concat("inside(S, <7.5, 0, 0>) = ", str(inside(S, <7.5, 0, 0>), 0, 0), "\n")
#debug concat("inside(S, <5, 1.5, 0>) = ", str(inside(S, <5, 1.5, 0>), 0, 0), "\n")
