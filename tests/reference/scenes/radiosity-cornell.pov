// A Cornell box, open towards the camera, lit by one light under the ceiling, with
// radiosity's default settings apart from more rays per sample: the walls bleed red and
// green onto the white boxes and the ceiling is lit only by radiosity.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 60 }
}
camera { location <0, 2.5, -10> look_at <0, 2.4, 0> angle 33 }
light_source { <0, 4.5, -0.5> rgb 1 }
#declare White = texture { pigment { rgb 0.75 } finish { diffuse 0.8 } }
#declare Wall = box { <-2.5, -0.1, -2.5>, <2.5, 0, 2.5> }
object { Wall texture { White } }
object { Wall translate y * 5.1 texture { White } }
object { Wall rotate x * -90 translate <0, 2.5, 2.6> texture { White } }
object { Wall rotate z * -90 translate <-2.6, 2.5, 0> pigment { rgb <0.7, 0.1, 0.08> } finish { diffuse 0.8 } }
object { Wall rotate z * 90 translate <2.6, 2.5, 0> pigment { rgb <0.1, 0.6, 0.12> } finish { diffuse 0.8 } }
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> rotate y * 20 translate <0.9, 0, -0.6> texture { White } }
box { <-0.7, 0, -0.7>, <0.7, 3, 0.7> rotate y * -18 translate <-0.9, 0, 0.8> texture { White } }
