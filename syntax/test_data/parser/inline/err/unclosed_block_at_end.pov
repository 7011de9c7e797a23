sphere { 0, 1
light_source { 0 color 1 }
