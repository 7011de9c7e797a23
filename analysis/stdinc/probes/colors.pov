#version 3.7;
// Colour-space macros of colors.inc on primaries, greys, mixtures and out-of-range input.
#include "colors.inc"
#macro Show(Label, C)
  #local V = color C;
  #debug concat(Label, " ", str(V.red, 0, 5), " ", str(V.green, 0, 5), " ", str(V.blue, 0, 5),
                " ", str(V.filter, 0, 5), " ", str(V.transmit, 0, 5), "\n")
#end
#declare Samples = array[10] {
  Red, Green, Blue, Yellow, White, Black, Gray50, rgbft <0.2, 0.4, 0.9, 0.3, 0.1>,
  rgb <0.9, 0.1, 0.5>, rgb <0.3, 0.3, 0.1>
}
#for (I, 0, 9)
  Show(concat("hsl", str(I, 0, 0)), CRGB2HSL(Samples[I]))
  Show(concat("hsv", str(I, 0, 0)), CRGB2HSV(Samples[I]))
  Show(concat("rgb-hsl", str(I, 0, 0)), CHSL2RGB(CRGB2HSL(Samples[I])))
  Show(concat("rgb-hsv", str(I, 0, 0)), CHSV2RGB(CRGB2HSV(Samples[I])))
#end
#for (H, -60, 420, 30)
  Show(concat("hue", str(H, 0, 0)), CH2RGB(H))
  Show(concat("fromhsl", str(H, 0, 0)), CHSL2RGB(<H, 0.7, 0.3, 0.2, 0>))
  Show(concat("fromhsv", str(H, 0, 0)), CHSV2RGB(<H, 0.6, 0.8, 0, 0.4>))
#end
