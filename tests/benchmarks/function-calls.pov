// 100,000 calls of the gallery gyroid's compiled functions from an SDL loop. With
// function-calls-baseline.pov, the same loop without the calls, it gives the cost of a
// function call natively, in wasm and in POV-Ray: run both through
// `cargo run --release -p tests --bin eval-benchmark` and divide the difference by 100,000.
#version 3.7;
#declare K = 2.0;
#declare R = 4;
#declare Slab = function(x, y, z) {
  abs(sin(K*x)*cos(K*y) + sin(K*y)*cos(K*z) + sin(K*z)*cos(K*x)) - (0.15 + 0.32 * (x*x + y*y + z*z) / (R*R))
}
#declare SphereSD = function(x, y, z) { sqrt(x*x + y*y + z*z) - R }
#declare SmoothMax = function(a, b, k) { (a + b + sqrt((a - b)*(a - b) + k*k)) / 2 }
#declare Gyroid = function { SmoothMax(Slab(x, y, z), SphereSD(x, y, z), 0.25) }
#declare S = 0;
#declare I = 0;
#while (I < 100000)
  #declare S = S + Gyroid(I*1e-6, 0.5 - I*1e-6, 1 + I*1e-6);
  #declare I = I + 1;
#end
#debug concat(str(S, 0, 6), "\n")
camera { location -5*z look_at 0 }
