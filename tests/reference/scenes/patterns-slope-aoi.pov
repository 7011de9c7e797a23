// Pattern fidelity: slope and aoi, which look at the surface's normal and the ray. A
// perspective camera (the ray's direction changes across the picture), a mirror floor
// (reflected rays see aoi too), a slope texture map, slope with ranges, altitude and
// point_at, a normal map chosen by aoi, a pigment over a layer's bumps, and the inside of
// a shell (the normal turned to face the ray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.2, 0.25, 0.3> }
camera { location <0, 3.2, -7> look_at <0, 0.6, 0> angle 60 }
light_source { <-6, 10, -8> color rgb 1 }
#declare Map = color_map {
  [0.0 rgb <0.8, 0.1, 0.1>] [0.25 rgb <0.95, 0.7, 0.2>] [0.5 rgb <0.2, 0.7, 0.3>]
  [0.75 rgb <0.2, 0.4, 0.9>] [1.0 rgb <0.95, 0.95, 0.95>]
}
#declare F = finish { ambient 0.35 diffuse 0.65 }
plane { y, 0
  pigment { aoi color_map { Map } }
  finish { ambient 0.3 diffuse 0.4 reflection 0.3 }
}
// Rock and snow: the texture is chosen by how steep the surface is.
sphere { <-2.6, 1, 0.5>, 1
  texture { slope { y, 0.5, 1 }
    texture_map {
      [0.4 pigment { rgb <0.45, 0.35, 0.25> } finish { F }]
      [0.6 pigment { rgb 1 } finish { F }]
    }
  }
}
// Slope blended with altitude, in a rotated and scaled pattern.
torus { 0.8, 0.35 rotate x*-60 translate <-0.6, 1.1, 1.5>
  pigment { slope { <1, 2, 0> altitude y, 0.6, 1.6 } color_map { Map } frequency 1.5 }
  finish { F }
}
// Facing a point, with a range.
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> rotate y*35 translate <1.2, 0, -0.6>
  pigment { slope { point_at <3, 4, -6>, 0.4, 1 } color_map { Map } }
  finish { F }
}
// The angle of incidence on a sphere, with a phase.
sphere { <3, 1, 1.2>, 1
  pigment { aoi color_map { Map } phase 0.1 }
  finish { F }
}
// A normal map chosen by aoi: smooth where the ray meets the surface head-on, ribbed at the rim.
sphere { <-0.4, 0.55, -1.6>, 0.55
  pigment { rgb <0.9, 0.8, 0.6> }
  normal { aoi normal_map { [0.5 gradient y 2 scale 0.05] [0.8 gradient y 0] } }
  finish { F }
}
// A slope pigment over the layer's own gradient bumps, which tilt the normal it sees.
cylinder { <2.4, 0, -1.8>, <2.4, 1.3, -1.8>, 0.45
  pigment { slope x color_map { Map } }
  normal { gradient y 0.8 scale 0.2 }
  finish { F }
}
// The inside of a cut shell: its normal turned to face the ray.
sphere { 0, 0.7 clipped_by { plane { -z, 0.2 } } rotate y*200 translate <0.2, 2.6, 2.5>
  pigment { slope y color_map { Map } }
  finish { F }
}
