#if (A) sphere { 0, 1 } #elseif (B) box { 0, 1 } #else #debug "none" #end
#ifdef (Foo) #declare Bar = Foo; #end
#switch (N) #case (1) #debug "one" #break #range (2, 5) #debug "few" #else #debug "many" #end
