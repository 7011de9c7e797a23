// text from a TrueType font: kerned glyphs with curved outlines extruded in z, turned so
// the side walls show, and a second string with a per-character offset. The font is the
// one Povrayst bundles, found by POV-Ray through the scene's library path; Povrayst draws
// the same font when the file is not supplied, with a warning.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -5> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 6, -6> rgb 1 }
light_source { <5, 1, -3> rgb 0.4 shadowless }
background { rgb <0.15, 0.15, 0.2> }
#declare Font = "../../../analysis/fonts/DejaVuSerif-Latin1.ttf";
text { ttf Font "AVog&Q@" 0.4, 0
  pigment { rgb <1, 0.7, 0.3> } finish { ambient 0.15 diffuse 0.7 phong 0.5 }
  rotate y * -25 translate <-2.4, 0.6, 0> }
text { ttf Font "Kerning, 3.7!" 0.2, <0.05, -0.04, 0>
  pigment { rgb <0.4, 0.8, 1> } finish { ambient 0.15 diffuse 0.7 }
  scale 0.6 rotate x * -30 translate <-2, -0.6, -0.5> }
