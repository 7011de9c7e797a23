#version 3.7;
#debug "before\n"
#declare A = sor { 7, <0, 0> <0.1, 0> <0.6, 0.5> <0.2, 0.8> <0.2, 0.9> <0.3, 1> <0.5, 0.95> open }
#declare B = sor { 5, <0, 2.5> <1, 1> <1, 2> <1, 3> <0, 2.01> }
#debug "sors with dipping end points parse\n"
