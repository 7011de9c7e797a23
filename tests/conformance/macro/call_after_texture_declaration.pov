#version 3.7;
#declare T = texture { pigment { rgb 1 } }
#macro Show(Tex) #local Copy = texture { Tex } #debug "shown\n" #end
Show(T)
#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }
Show(L)
