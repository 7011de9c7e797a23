// light_group: lights that shine on their group's objects only; global_lights letting the
// scene's lights in; a nested group, whose objects POV-Ray lights with the innermost
// group's lights and the scene's lights as the outermost group says; an object outside
// every group still casting a shadow of a group's light; light groups in a difference.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0.5, 0> }
light_source { <5, 10, -5> rgb 0.7 }
#declare RedLight = light_source { <-5, 5, -5> rgb <1, 0.2, 0.2> }
light_group {
  light_source { RedLight }
  sphere { <-2, 1, 0>, 1 pigment { rgb 1 } }
  global_lights off
}
light_group {
  light_source { <0, 6, -3> rgb <0.2, 0.2, 1> }
  sphere { <1.2, 1, 0>, 1 pigment { rgb 1 } }
  light_group {
    light_source { <5, 2, -5> rgb <0.2, 1, 0.2> }
    box { <2.5, 0, -0.5>, <3.5, 1, 0.5> pigment { rgb 1 } }
  }
  global_lights on
}
// Lit by the scene's light only, it shades the blue group light's sphere.
box { <0.3, 3.9, -1.8>, <0.9, 4, -1.2> pigment { rgb 1 } }
difference {
  light_group {
    sphere { 0, 1 pigment { rgb 1 } }
    light_source { <-100, 0, -100> rgb <1, 0, 0> }
    global_lights off
  }
  light_group {
    sphere { <0, 1, 0>, 1 pigment { rgb 1 } }
    light_source { <100, 100, 0> rgb <0, 0, 1> }
    global_lights off
  }
  rotate <-45, 0, 0>
  translate <-1, 0.5, -3>
}
plane { y, 0 pigment { rgb 0.8 } }
