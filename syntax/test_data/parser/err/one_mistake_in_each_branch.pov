#if (A)
  sphere { 0, 1
#else
  box { 0, 1 } }
#end
plane { y, 0 }
