#if (Merge) merge { #else union { #end
  sphere { 0, 1 }
  sphere { x, 1 }
}
#if (A) #else object { B #end translate x }
