#macro M(A)
  sphere { A, 1
#end
union {
  box { 0, 1 }
  #if (1)
    cone { 0, 1, y, 0
  #end
}
plane { y, 0 }
