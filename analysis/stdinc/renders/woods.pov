#version 3.7;
// Every texture and grain of woods.inc on a slightly tilted box.
#include "woods.inc"
global_settings { assumed_gamma 1 }
camera { orthographic location <4.5, 3.5, -20> look_at <4.5, 3.5, 0> right 10 * 4 / 3 * x up 10 * y }
light_source { <-20, 30, -40> rgb 1 }
#declare Textures = array[35] {
  T_Wood1, T_Wood2, T_Wood3, T_Wood4, T_Wood5, T_Wood6, T_Wood7, T_Wood8, T_Wood9, T_Wood10,
  T_Wood11, T_Wood12, T_Wood13, T_Wood14, T_Wood15, T_Wood16, T_Wood17, T_Wood18, T_Wood19, T_Wood20,
  T_Wood21, T_Wood22, T_Wood23, T_Wood24, T_Wood25, T_Wood26, T_Wood27, T_Wood28, T_Wood29, T_Wood30,
  T_Wood31, T_Wood32, T_Wood33, T_Wood34, T_Wood35
}
#for (I, 0, 34)
  box { <-0.45, -0.45, -0.45>, <0.45, 0.45, 0.45> texture { Textures[I] rotate <3, 40, 0> }
    rotate <20, 30, 0> translate <mod(I, 10), 7 - div(I, 10), 0> }
#end
#declare Grains = array[19] {
  P_WoodGrain1B, P_WoodGrain2B, P_WoodGrain3B, P_WoodGrain4B, P_WoodGrain5B, P_WoodGrain6B, P_WoodGrain7B,
  P_WoodGrain8B, P_WoodGrain9B, P_WoodGrain10B, P_WoodGrain11B, P_WoodGrain12B, P_WoodGrain13B,
  P_WoodGrain14B, P_WoodGrain15B, P_WoodGrain16B, P_WoodGrain17B, P_WoodGrain18B, P_WoodGrain19B
}
#for (I, 0, 18)
  box { <-0.45, -0.45, -0.45>, <0.45, 0.45, 0.45>
    pigment { Grains[I] color_map { [0 rgb <0.9, 0.7, 0.4>] [1 rgb <0.3, 0.15, 0.05>] } rotate <3, 40, 0> }
    rotate <20, 30, 0> translate <mod(I, 10), 3 - div(I, 10), 0> }
#end
