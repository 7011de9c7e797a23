#while (I < 3)
  #if (I = 1)
    sphere { 0, 1 }
  #local I = I + 1;
#end
camera { }
