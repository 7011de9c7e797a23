#version 3.7;
#declare S = sphere {
  0, 1
  #debug "inside a sphere\n"
}
