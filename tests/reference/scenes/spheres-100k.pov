// A hundred thousand small spheres scattered in a cube with parse-time random numbers:
// the scene that the bounding volume hierarchy over objects must make cheap to trace.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <18, 14, -36> look_at 0 angle 42 }
light_source { <-30, 40, -50> rgb 1 }
#declare Stream = seed(2024);
#for (I, 1, 100000)
  sphere {
    <rand(Stream), rand(Stream), rand(Stream)> * 20 - 10, 0.15
    pigment { rgb <rand(Stream), rand(Stream), rand(Stream)> * 0.8 + 0.2 }
  }
#end
