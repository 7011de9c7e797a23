#version 3.7;
// The macros of rand.inc: six draws each from a fresh stream, so each macro's sequence
// of rand() calls is checked as well as its formula.
#include "rand.inc"
#macro ShowF(Label, Value) #debug concat(Label, " ", str(Value, 0, 6), "\n") #end
#macro ShowV(Label, Value) #debug concat(Label, " ", vstr(3, Value, " ", 0, 6), "\n") #end
#declare S = seed(1); #for (I, 1, 6) ShowF("SRand", SRand(S)) #end
#declare S = seed(2); #for (I, 1, 6) ShowF("RRand", RRand(-3, 5, S)) #end
#declare S = seed(3); #for (I, 1, 6) ShowV("VRand", VRand(S)) #end
#declare S = seed(4); #for (I, 1, 6) ShowV("VRand_In_Box", VRand_In_Box(<-1, 2, 3>, <4, 2.5, -1>, S)) #end
#declare S = seed(5); #for (I, 1, 6) ShowV("VRand_In_Sphere", VRand_In_Sphere(S)) #end
#declare S = seed(6); #for (I, 1, 6) ShowV("VRand_On_Sphere", VRand_On_Sphere(S)) #end
#declare S = seed(7); #for (I, 1, 6) ShowF("Rand_Cauchy", Rand_Cauchy(2, 0.5, S)) #end
#declare S = seed(9); #for (I, 1, 6) ShowF("Rand_Normal", Rand_Normal(1, 2, S)) #end
#declare S = seed(10); #for (I, 1, 6) ShowF("Rand_Gauss", Rand_Gauss(1, 2, S)) #end
#declare S = seed(11); #for (I, 1, 6) ShowF("Rand_Gamma big", Rand_Gamma(2.5, 1.5, S)) #end
#declare S = seed(12); #for (I, 1, 6) ShowF("Rand_Gamma one", Rand_Gamma(1, 1.5, S)) #end
#declare S = seed(13); #for (I, 1, 6) ShowF("Rand_Gamma small", Rand_Gamma(0.5, 1.5, S)) #end
#declare S = seed(14); #for (I, 1, 6) ShowF("Rand_Beta", Rand_Beta(2, 3, S)) #end
#declare S = seed(15); #for (I, 1, 6) ShowF("Rand_Chi_Square", Rand_Chi_Square(4, S)) #end
#declare S = seed(17); #for (I, 1, 6) ShowF("Rand_Triangle", Rand_Triangle(1, 5, 2, S)) #end
#declare S = seed(18); #for (I, 1, 6) ShowF("Rand_Erlang", Rand_Erlang(2, 3, S)) #end
#declare S = seed(19); #for (I, 1, 6) ShowF("Rand_Exp", Rand_Exp(0.5, S)) #end
#declare S = seed(20); #for (I, 1, 6) ShowF("Rand_Lognormal", Rand_Lognormal(3, 1, S)) #end
#declare S = seed(21); #for (I, 1, 6) ShowF("Rand_Pareto", Rand_Pareto(2, S)) #end
#declare S = seed(22); #for (I, 1, 6) ShowF("Rand_Weibull", Rand_Weibull(2, 1.5, S)) #end
#declare S = seed(23); #for (I, 1, 6) ShowF("Rand_Bernoulli", Rand_Bernoulli(0.3, S)) #end
#declare S = seed(24); #for (I, 1, 6) ShowF("Prob", Prob(0.7, S)) #end
#declare S = seed(25); #for (I, 1, 6) ShowF("Rand_Binomial", Rand_Binomial(10, 0.4, S)) #end
#declare S = seed(26); #for (I, 1, 6) ShowF("Rand_Geo", Rand_Geo(0.3, S)) #end
#declare S = seed(27); #for (I, 1, 6) ShowF("Rand_Poisson", Rand_Poisson(3.5, S)) #end
// Rand_Spline is left out: POV-Ray 3.7's own cannot be used in a #declare.  So are
// Rand_Student and Rand_F_Dist: POV-Ray's methods could not be told black-box, so ours
// follow the textbook definitions and draw other numbers (see the README).
ShowF("RdmA", rand(RdmA))
ShowF("RdmB", rand(RdmB))
ShowF("RdmC", rand(RdmC))
ShowF("RdmD", rand(RdmD))
