/* Block comments /* nest */ in POV-Ray */
#declare deprecated once "use NewTex" OldTex = texture { pigment { color rgbf <1, 0.5, 0, 0.2> } };
#local Str = concat("a\"b", str(1.5e-3, 0, 2));
#macro Twice(A) (2 * A) #end
#if (Twice(3) >= 6 & clock_on) #debug "six\n" #else #warning "no" #end
union { sphere { <0, .5, 0>, Twice(0.25) } box { -1, 1 } translate x * pi }
