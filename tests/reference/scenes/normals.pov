// Normal fidelity: patterns used as bumps (gradient, onion, cylindrical, radial, spherical,
// marble with a sine wave), lit from one side so that the tilt of each normal shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb 0.1 }
camera { orthographic location <0, 0, -10> look_at 0 right 12*x up 8*y }
light_source { <-8, 6, -10> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.05 }
#macro Ball(X, Y, N)
  sphere { <X, Y, 0>, 1.7 pigment { rgb <0.8, 0.75, 0.6> } normal { N } finish { F } }
#end
Ball(-4, 2, normal { gradient x 0.6 scale 0.5 })
Ball( 0, 2, normal { onion 0.8 scale 0.4 })
Ball( 4, 2, normal { cylindrical 1 scale 1.5 })
Ball(-4, -2, normal { radial 0.7 frequency 8 })
Ball( 0, -2, normal { spherical 1.5 scale 1.7 })
Ball( 4, -2, normal { marble 0.6 sine_wave scale 0.6 })
