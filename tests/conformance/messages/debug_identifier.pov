#version 3.7;
#declare S = "from identifier\n";
#debug S
