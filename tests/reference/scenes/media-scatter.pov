// Scattering types in boxes lit from behind (between them and the wall): Mie hazy, Rayleigh and Henyey-Greenstein,
// with extinction, in front of a dark wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -8> look_at 0 angle 55 }
light_source { <0, 2, 3.5> rgb 1 }
plane { z, 5 hollow pigment { rgb 0.05 } finish { diffuse 0 ambient 1 } }
#declare Clear = texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }
box { <-3.4, -1.5, -1>, <-1.4, 1.5, 1> hollow texture { Clear }
  interior { media { scattering { 2, rgb <0.15, 0.1, 0.05> } } } }
box { <-1, -1.5, -1>, <1, 1.5, 1> hollow texture { Clear }
  interior { media { scattering { 4, rgb <0.2, 0.3, 0.4> } } } }
box { <1.4, -1.5, -1>, <3.4, 1.5, 1> hollow texture { Clear }
  interior { media { scattering { 5, rgb 0.2 eccentricity 0.6 extinction 0.5 } } } }
