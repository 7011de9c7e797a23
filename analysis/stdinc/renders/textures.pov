#version 3.7;
// Every pigment, texture and material of textures.inc on a sphere in front of a checkered
// backdrop.
#include "colors.inc"
#include "textures.inc"
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { orthographic location <6, 4.5, -20> look_at <6, 4.5, 0> right 13 * 4 / 3 * x up 13 * y }
light_source { <-20, 30, -40> rgb 1 }
plane { z, 1 pigment { checker rgb 0.3, rgb 0.8 scale 0.5 } }
#declare Pigments = array[24] {
  Jade, Red_Marble, White_Marble, Blood_Marble, Blue_Agate, Sapphire_Agate, Brown_Agate,
  Pink_Granite, Blue_Sky, Bright_Blue_Sky, Blue_Sky2, Blue_Sky3, Blood_Sky, Apocalypse, Clouds,
  FBM_Clouds, Cherry_Wood, Pine_Wood, Dark_Wood, Tan_Wood, White_Wood, Tom_Wood, DMFWood1, DMFWood2
}
#declare More_Pigments = array[9] {
  DMFWood3, DMFWood4, DMFWood5, DMFLightOak, DMFDarkOak, Candy_Cane, Peel, Y_Gradient, X_Gradient
}
#declare Textures = array[44] {
  PinkAlabaster, Shadow_Clouds, DMFWood6, EMBWood1, Yellow_Pine, Rosewood, Sandalwood,
  Glass, Glass2, Glass3, Green_Glass, NBglass, NBoldglass, NBwinebottle, NBbeerbottle, Ruby_Glass,
  Dark_Green_Glass, Yellow_Glass, Orange_Glass, Vicks_Bottle_Glass, Chrome_Texture, Brass_Texture,
  Gold_Texture, Bronze_Texture, Copper_Texture, Silver_Texture, Polished_Chrome, Polished_Brass,
  New_Brass, Spun_Brass, Brushed_Aluminum, Silver1, Silver2, Silver3, Brass_Valley, Rust,
  Rusty_Iron, Soft_Silver, New_Penny, Tinny_Brass, Gold_Nugget, Aluminum, Bright_Bronze, Water
}
#declare More_Textures = array[4] { Cork, Lightning1, Lightning2, Starfield }
#declare Materials = array[13] {
  M_Glass, M_Glass2, M_Glass3, M_Green_Glass, M_NB_Glass, M_NB_Old_Glass, M_NB_Winebottle_Glass,
  M_NB_Beerbottle_Glass, M_Ruby_Glass, M_Dark_Green_Glass, M_Yellow_Glass, M_Orange_Glass, M_Vicks_Bottle_Glass
}
#declare N = 0;
#macro Place() <mod(N, 12), 8.5 - div(N, 12), 0> #declare N = N + 1; #end
#for (I, 0, 23) sphere { Place(), 0.45 pigment { Pigments[I] } } #end
#for (I, 0, 8) sphere { Place(), 0.45 pigment { More_Pigments[I] } } #end
#for (I, 0, 43) sphere { Place(), 0.45 texture { Textures[I] } } #end
#for (I, 0, 3) sphere { Place(), 0.45 texture { More_Textures[I] } } #end
#for (I, 0, 12) sphere { Place(), 0.45 material { Materials[I] } } #end
sphere { Place(), 0.45 material { M_Water } }
sphere { Place(), 0.45 texture { Glass } interior { Glass_Interior } finish { Glass_Finish } }
sphere { Place(), 0.45 texture { pigment { Silver2_Colour } finish { Metal } } }
sphere { Place(), 0.45 texture { pigment { Silver3_Colour } finish { Metallic_Finish } } }
sphere { Place(), 0.45 texture { pigment { Silver1_Colour } finish { SilverFinish } } }
box { <-0.45, -0.45, -0.1>, <0.45, 0.45, 0> pigment { Tiles_Ptrn() color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } translate Place() }
box { <-0.45, -0.45, -0.1>, <0.45, 0.45, 0> pigment { Hex_Tiles_Ptrn() color_map { [0 rgb 0] [1 rgb 1] } rotate -90 * x scale 0.2 } translate Place() }
box { <-0.45, -0.45, -0.1>, <0.45, 0.45, 0> pigment { Star_Ptrn(0.4, 5, 2) color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } } translate Place() }
#declare Blue_Map = color_map { Jade_Map }
sphere { Place(), 0.45 pigment { marble turbulence 1 color_map { Red_Marble_Map } } }
sphere { Place(), 0.45 pigment { agate color_map { Blue_Agate_Map } } }
sphere { Place(), 0.45 pigment { bozo color_map { Blue_Sky_Map } } }
sphere { Place(), 0.45 pigment { wood color_map { Lightning_CMap2 } } }
