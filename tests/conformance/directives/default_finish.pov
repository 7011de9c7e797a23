#version 3.7;
#default { finish { ambient 0.3 } }
#debug "default accepted\n"
