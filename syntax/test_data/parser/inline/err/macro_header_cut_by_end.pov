#macro M(a #end )
#declare After = 1;
