sphere { 0, 1 } { pigment { Red } }
