union {
  sphere { 0, 1
  box { 0, 1 }
}
camera { }
