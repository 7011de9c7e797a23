#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Foo = color srgbt <51,76,102,127>/255;
#debug concat("Foo = <", vstr(5, Foo, ", ", 0, 3), ">\n")
#declare Foo = color srgb <0.2, 0.3, 0.4> transmit 0.5;
#debug concat("Foo = <", vstr(5, Foo, ", ", 0, 3), ">\n")
