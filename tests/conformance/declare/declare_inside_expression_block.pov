#version 3.7;
#declare Count = 0;
#declare U = union {
  sphere { 0, 1 }
  #declare Count = Count + 1;
  sphere { x, 1 }
  #declare Count = Count + 1;
}
#debug concat("Count = ", str(Count, 0, 0), "\n")
