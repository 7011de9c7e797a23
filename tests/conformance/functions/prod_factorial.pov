#version 3.7;
#declare Factorial = function(C) { prod(i, 1, C, i) }
#debug concat("Factorial(5) = ", str(Factorial(5), 0, 3), "\n")
#debug concat("Factorial(10) = ", str(Factorial(10), 0, 3), "\n")
