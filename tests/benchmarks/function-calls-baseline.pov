// The loop of function-calls.pov with the same arguments added up instead of passed to
// Gyroid: what the loop costs without the 100,000 function calls.
#version 3.7;
#declare K = 2.0;
#declare R = 4;
#declare Slab = function(x, y, z) {
  abs(sin(K*x)*cos(K*y) + sin(K*y)*cos(K*z) + sin(K*z)*cos(K*x)) - (0.15 + 0.32 * (x*x + y*y + z*z) / (R*R))
}
#declare SphereSD = function(x, y, z) { sqrt(x*x + y*y + z*z) - R }
#declare SmoothMax = function(a, b, k) { (a + b + sqrt((a - b)*(a - b) + k*k)) / 2 }
#declare Gyroid = function { SmoothMax(Slab(x, y, z), SphereSD(x, y, z), 0.25) }
#declare Unused = Gyroid(0, 0, 0);
#declare S = 0;
#declare I = 0;
#while (I < 100000)
  #declare S = S + (I*1e-6 + 0.5 - I*1e-6 + 1 + I*1e-6);
  #declare I = I + 1;
#end
#debug concat(str(S, 0, 6), "\n")
camera { location -5*z look_at 0 }
