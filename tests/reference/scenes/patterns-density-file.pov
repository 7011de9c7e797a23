// density_file: a 12 x 10 x 8 grid of 16-bit voxels (assets/ring.df3, a ring of varying
// thickness) as a pigment without and with trilinear interpolation, as a normal, and as
// the density of an emitting medium.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.4, 1.2, -5> look_at <0.4, 0.4, 0> angle 52 }
light_source { <-4, 6, -5> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }

#declare Ring = pigment {
  density_file df3 "assets/ring.df3"
  color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb 1] }
  translate -0.5 scale 1.6 translate x * -1.3
}
box { <-2.1, -0.8, 0>, <-0.5, 0.8, 0.8>
  pigment { Ring } finish { ambient 0.4 diffuse 0.6 } }
box { <-0.4, -0.8, 0>, <1.2, 0.8, 0.8>
  pigment { density_file df3 "assets/ring.df3" interpolate 1
    color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb 1] }
    translate -0.5 scale 1.6 translate x * 0.4 }
  finish { ambient 0.4 diffuse 0.6 } }
box { <1.3, -0.8, 0>, <2.9, 0.8, 0.8>
  pigment { rgb 0.8 }
  normal { density_file df3 "assets/ring.df3", 3 interpolate 1 translate -0.5 scale 1.6 translate x * 2.1 }
  finish { ambient 0.2 diffuse 0.8 } }
sphere { <0.4, 1.75, 1>, 0.75 hollow pigment { rgbt 1 }
  interior { media { emission 3 method 1 intervals 20 samples 2, 2
    density { density_file df3 "assets/ring.df3" interpolate 1
      color_map { [0 rgb 0] [1 rgb <1, 0.6, 0.2>] }
      translate -0.5 scale 1.4 rotate x * -60 translate <0.4, 1.75, 1> } } } }
