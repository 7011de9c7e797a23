#version 3.7;
// Every colour map of woodmaps.inc and of the .map files as a band of gradient x, over a
// checkered backdrop that shows through the transparent ones.
#include "woodmaps.inc"
#include "ash.map"
#include "benediti.map"
#include "bubinga.map"
#include "cedar.map"
#include "marbteal.map"
#include "orngwood.map"
#include "pinkmarb.map"
#include "rdgranit.map"
#include "teak.map"
#include "whiteash.map"
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 24, -10> look_at <0.5, 24, 0> right 1.2 * x up 48.5 * y }
plane { z, 1 pigment { checker rgb 0.1, rgb 0.9 scale 0.05 } finish { ambient 1 diffuse 0 } }
#declare Maps = array[48] {
  M_Wood1A, M_Wood1B, M_Wood2A, M_Wood2B, M_Wood3A, M_Wood3B, M_Wood4A, M_Wood4B, M_Wood5A, M_Wood5B,
  M_Wood6A, M_Wood6B, M_Wood7A, M_Wood7B, M_Wood8A, M_Wood8B, M_Wood9A, M_Wood9B, M_Wood10A, M_Wood10B,
  M_Wood11A, M_Wood11B, M_Wood12A, M_Wood12B, M_Wood13A, M_Wood13B, M_Wood14A, M_Wood14B, M_Wood15A, M_Wood15B,
  M_Wood16A, M_Wood16B, M_Wood17A, M_Wood17B, M_Wood18A, M_Wood18B, M_Wood19A, M_Wood19B,
  M_Ash, M_Benediti, M_Bubinga, M_Cedar, M_MarbTeal, M_Orangewood, M_PinkMarb, M_RedGranite, M_Teak, M_WhiteAsh
}
#for (I, 0, 47)
  box { <0, I, 0>, <0.9999, I + 0.9, 0.1>
    pigment { gradient x color_map { Maps[I] } } finish { ambient 1 diffuse 0 } }
#end
