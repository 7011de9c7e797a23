#macro Ring(R)
  torus { R, 0.1 }

sphere { 0, 1 }
camera { }
