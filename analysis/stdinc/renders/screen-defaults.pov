#version 3.7;
// screen.inc's default camera, and the same after Reset_Camera.
#include "colors.inc"
#include "screen.inc"
global_settings { assumed_gamma 1 }
Set_Camera_Location(<1, 2, -5>)
Set_Camera_Look_At(<0, 0.5, 0>)
Set_Camera_Sky(<0.2, 1, 0>)
Set_Camera_Zoom(1.5)
Set_Camera_Aspect(3, 2)
Reset_Camera()
Set_Camera_Location(<0, 1, -6>)
light_source { <-10, 20, -20> rgb 1 }
plane { y, 0 pigment { checker rgb 0.3, rgb 0.8 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.8, 0.3, 0.2> } }
Screen_Object(text { ttf "timrom.ttf" "POV" 0.1, 0 pigment { White } }, <0.5, 0.9>, 0, false, 0.05)
