#macro Ring(R, optional Thickness)
  torus { R, Thickness }
#end
#macro Half(V) V/2 #end
