#version 3.7;
#debug concat("pow(sin(0.7),2)+pow(cos(0.7),2) = ", str(pow(sin(0.7),2)+pow(cos(0.7),2), 0, 12), "\n")
#debug concat("tan(0.3)-sin(0.3)/cos(0.3) = ", str(tan(0.3)-sin(0.3)/cos(0.3), 0, 12), "\n")
