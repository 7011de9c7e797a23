pigment { color rgb <1, 0, 0> filter 0.5 }
pigment { color Red transmit 0.2 }
pigment { color red 1 green 0.5 blue 0 }
pigment { rgbft <1, 1, 1, 0.5, 0> * 0.5 }
