// Lemon fidelity. POV-Ray 3.7 has no lemon (it came with 3.8), so its reference draws
// the same solid as a lathe of Bezier arcs (within 1e-5 of the circle) closed by its end
// discs; the lemon test renders `lemon` in its place (Native = 1) against that picture.
#version 3.7;
#declare S = 1;
#declare Native = 0;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.25, 0.3, 0.4> }
camera { location <0, 3, -7>*S look_at <0, 0.6, 0>*S angle 45 }
light_source { <-5, 9, -6>*S color rgb 1.1 }
light_source { <6, 4, -3>*S color rgb 0.4 }
#declare F = finish { specular 0.5 roughness 0.02 }
plane { y, -0.01*S pigment { rgb 0.7 } }
// The arc of radius R centred at (-C, H) from (R1, 0) to (R2, L), as Bezier pieces.
#macro Lemon_Lathe(L, R1, R2, R)
  #local M = (L*L - (R1*R1 - R2*R2))/(2*L);
  #local K = -(R1 - R2)/L;
  #local A = 1 + K*K;
  #local B = R1 + M*K;
  #local C0 = R1*R1 + M*M - R*R;
  #local C = (-B + sqrt(B*B - A*C0))/A;
  #local H = M + K*C;
  #local Start = atan2(0 - H, R1 + C);
  #local End = atan2(L - H, R2 + C);
  #local N = 8;
  #local Step = (End - Start)/N;
  #local Kappa = 4/3*tan(Step/4)*R;
  lathe { bezier_spline 4*N + 8,
    <0, 0>, <R1/3, 0>, <2*R1/3, 0>, <R1, 0>,
    #local I = 0;
    #while (I < N)
      #local A0 = Start + I*Step;
      #local A1 = A0 + Step;
      <R*cos(A0) - C, H + R*sin(A0)>,
      <R*cos(A0) - C - Kappa*sin(A0), H + R*sin(A0) + Kappa*cos(A0)>,
      <R*cos(A1) - C + Kappa*sin(A1), H + R*sin(A1) - Kappa*cos(A1)>,
      <R*cos(A1) - C, H + R*sin(A1)>,
      #local I = I + 1;
    #end
    <R2, L>, <2*R2/3, L>, <R2/3, L>, <0, L>
  }
#end
#macro Lemon(Base, R1, Cap, R2, R)
  #if (Native)
    lemon { Base, R1, Cap, R2, R }
  #else
    object { Lemon_Lathe(vlength(Cap - Base), R1, R2, R)
      #local Axis = vnormalize(Cap - Base);
      Reorient_Trans(y, Axis) translate Base }
  #end
#end
#include "transforms.inc"
object { Lemon(<0, 0, 0>, 0, <0, 2, 0>, 0, 1.25) translate <-2, 0, 0> scale S pigment { rgb <0.9, 0.3, 0.2> } finish { F } }
object { Lemon(<0, 0, 0>, 0.5, <0, 1.6, 0>, 0.3, 1.2) translate <0, 0, 0> scale S pigment { rgb <0.2, 0.7, 0.3> } finish { F } }
object { Lemon(<0, 0.5, 0>, 0.2, <1.5, 1, 0>, 0.4, 2) translate <1.2, 0, -0.5> scale S pigment { rgb <0.2, 0.4, 0.9> } finish { F } }
