#version 3.7;
#declare Here = <1,2,3>;
#declare There = <3,4,5>;
#declare Route = There - Here;
#declare Route = Route + <1,1,1>;
#debug concat("Route = <", vstr(3, Route, ", ", 0, 1), ">\n")
