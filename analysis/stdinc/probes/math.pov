#version 3.7;
// The functions and macros of math.inc on ordinary and edge-case input.
#include "math.inc"
#macro ShowF(Label, Value) #debug concat(Label, " ", str(Value, 0, 6), "\n") #end
#macro ShowV(Label, Value) #debug concat(Label, " ", vstr(3, Value, " ", 0, 6), "\n") #end
#macro ShowV5(Label, Value) #debug concat(Label, " ", vstr(5, Value, " ", 0, 6), "\n") #end
#declare Floats = array[9] { -3, -2.5, -1, -0.25, 0, 0.5, 1, 2, 7.75 }
#for (I, 0, 8)
  #local N = Floats[I];
  ShowF(concat("even ", str(N, 0, 2)), even(N))
  ShowF(concat("odd ", str(N, 0, 2)), odd(N))
  ShowF(concat("sgn ", str(N, 0, 2)), sgn(N))
  ShowF(concat("clip ", str(N, 0, 2)), clip(N, -1, 1.5))
  ShowF(concat("clamp ", str(N, 0, 2)), clamp(N, -1, 1.5))
  ShowF(concat("adj_range ", str(N, 0, 2)), adj_range(N, 2, 5))
  ShowF(concat("adj_range2 ", str(N, 0, 2)), adj_range2(N, -1, 3, 10, 20))
  ShowF(concat("f_sqr ", str(N, 0, 2)), f_sqr(N))
  ShowF(concat("sind ", str(N, 0, 2)), sind(N * 40))
  ShowF(concat("cosd ", str(N, 0, 2)), cosd(N * 40))
  ShowF(concat("tand ", str(N, 0, 2)), tand(N * 10))
  ShowF(concat("atand ", str(N, 0, 2)), atand(N))
  ShowF(concat("atan2d ", str(N, 0, 2)), atan2d(N, -1.5))
  #if (abs(N) <= 1)
    ShowF(concat("asind ", str(N, 0, 2)), asind(N))
    ShowF(concat("acosd ", str(N, 0, 2)), acosd(N))
  #end
  ShowF(concat("max3 ", str(N, 0, 2)), max3(N, 0.3, -N / 2))
  ShowF(concat("min3 ", str(N, 0, 2)), min3(N, 0.3, -N / 2))
#end
#for (M, -2, 3)
  ShowF(concat("Interpolate method ", str(M, 0, 0)), Interpolate(0.3, 0, 1, 2, 12, M))
  ShowF(concat("Interpolate offset ", str(M, 0, 0)), Interpolate(-1, -2, 2, 0, 10, M))
#end
ShowF("Interpolate doc1", Interpolate(0.5, 0, 1, 0, 10, 1))
ShowF("Interpolate doc2", Interpolate(0.0, -2, 2, 0, 10, 1))
ShowF("Interpolate doc3", Interpolate(0.5, 0, 1, 0, 10, 2))
#declare Values = array[7] { 3, 1.5, -2, 8, 4.25, 4, 0 }
ShowF("Mean", Mean(Values))
ShowF("Std_Dev", Std_Dev(Values, Mean(Values)))
ShowV("Mean vectors", Mean(array[3] { <1, 2, 3>, <0, -1, 5>, <2, 2, 2> }))
GetStats(Values)
#for (I, 0, 4) ShowF(concat("StatisticsArray ", str(I, 0, 0)), StatisticsArray[I]) #end
#declare A = <1, -2, 0.5>;
#declare B = <0.3, 0.4, -2>;
ShowV("VSqr", VSqr(A))
ShowV("VPow", VPow(<1, 2, 0.5>, 3))
ShowV5("VPow5D", VPow5D(<1, 2, 0.5, 3, 4>, 2))
ShowF("VEq same", VEq(A, A))
ShowF("VEq different", VEq(A, B))
ShowF("VEq5D same", VEq5D(<1, 2, 3, 4, 5>, <1, 2, 3, 4, 5>))
ShowF("VEq5D different", VEq5D(<1, 2, 3, 4, 5>, <1, 2, 3, 4, 6>))
ShowF("VZero zero", VZero(<0, 0, 0>))
ShowF("VZero A", VZero(A))
ShowF("VZero5D zero", VZero5D(<0, 0, 0, 0, 0>))
ShowF("VZero5D other", VZero5D(<0, 0, 0, 0, 1>))
ShowF("VLength5D", VLength5D(<1, 2, 3, 4, 5>))
ShowV5("VNormalize5D", VNormalize5D(<1, 2, 3, 4, 5>))
ShowF("VDot5D", VDot5D(<1, 2, 3, 4, 5>, <5, 4, 3, 2, 1>))
ShowF("VCos_Angle", VCos_Angle(A, B))
ShowF("VAngle", VAngle(A, B))
ShowF("VAngleD", VAngleD(A, B))
ShowF("VRotation +", VRotation(x, y, z))
ShowF("VRotation -", VRotation(x, y, -z))
ShowF("VRotationD +", VRotationD(x, <1, 1, 0>, z))
ShowF("VRotationD -", VRotationD(x, <1, 1, 0>, -z))
ShowF("VRotationD zero axis", VRotationD(x, <1, -1, 0>, <0, 0, 0>))
ShowF("VDist", VDist(A, B))
ShowV("VPerp_To_Vector x", VPerp_To_Vector(x))
ShowV("VPerp_To_Vector y", VPerp_To_Vector(y))
ShowV("VPerp_To_Vector z", VPerp_To_Vector(z))
ShowV("VPerp_To_Vector A", VPerp_To_Vector(A))
ShowV("VPerp_To_Vector B", VPerp_To_Vector(B))
ShowV("VPerp_To_Vector diagonal", VPerp_To_Vector(<1, 1, 1>))
ShowV("VPerp_To_Plane", VPerp_To_Plane(A, B))
ShowV("VPerp_Adjust", VPerp_Adjust(A, B))
ShowV("VProject_Plane", VProject_Plane(A, B))
ShowV("VProject_Axis", VProject_Axis(A, B))
ShowF("VMin", VMin(A))
ShowF("VMax", VMax(A))
ShowV("VWith_Len", VWith_Len(A, 3))
#declare Field = function { x * x * y + sin(z) * 3 }
#declare Fx = function { y * z }
#declare Fy = function { x * x }
#declare Fz = function { x + y * z * z }
#declare P0 = <0.4, -1.2, 0.7>;
ShowV("vGradient", vGradient(Field, P0))
ShowF("Gradient_Length", Gradient_Length(Field, P0))
ShowF("Gradient_Directional", Gradient_Directional(Field, P0, <1, 2, 2>))
ShowV("vCurl", vCurl(Fx, Fy, Fz, P0))
ShowF("Divergence", Divergence(Fx, Fy, Fz, P0))
#declare G = fn_Gradient(Field);
ShowF("fn_Gradient", G(P0.x, P0.y, P0.z))
#declare GD = fn_Gradient_Directional(Field, <1, 2, 2>);
ShowF("fn_Gradient_Directional", GD(P0.x, P0.y, P0.z))
#declare D = fn_Divergence(Fx, Fy, Fz);
ShowF("fn_Divergence", D(P0.x, P0.y, P0.z))
SetGradientAccuracy(0.1)
ShowF("accuracy", __Gradient_Fn_Accuracy_)
ShowV("vGradient coarse", vGradient(Field, P0))
