#declare = 1;
#declare C 3;
#declare E = ;
