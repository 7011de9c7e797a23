#macro Open() union { #end
#macro Close() } #end
#macro Tail() , 1 } #end
