#version 3.7;
// The objects that the macros of shapes.inc build, seen through their bounding boxes,
// inside() on a grid across the box and where rays from all around hit them.
#include "shapes.inc"
#macro Probe(Name, Shape) ProbeWith(Name, Shape, true, 4) #end
#macro ProbeSurface(Name, Shape) ProbeWith(Name, Shape, false, 4) #end
// Text is compared to 3 decimals: our letter placement computes the same positions in a
// different order, which moves some figures by 1e-4.
#macro ProbeText(Name, Shape) ProbeWith(Name, Shape, true, 3) #end
#macro ProbeWith(Name, Shape, Solid, Digits)
  #local Object = object { Shape }
  #local Low = min_extent(Object);
  #local High = max_extent(Object);
  #debug concat(Name, " extent ", vstr(3, Low, " ", 0, Digits), " / ", vstr(3, High, " ", 0, Digits), "\n")
  #local Size = High - Low;
  #local Middle = (Low + High) / 2;
  #if (Solid)
    #for (I, 0, 6)
      #local Row = "";
      #for (J, 0, 6)
        #for (K, 0, 6)
          #local P = Low + Size * <I + 0.41, J + 0.37, K + 0.43> / 7.2;
          #local Row = concat(Row, str(inside(Object, P), 0, 0));
        #end
      #end
      #debug concat(Name, " inside ", Row, "\n")
    #end
  #end
  #local Reach = vlength(Size) + 1;
  #for (D, 0, 13)
    #local Dir = array[14] { x, -x, y, -y, z, -z, <1, 1, 1>, <-1, 1, 1>, <1, -1, 1>, <1, 1, -1>,
                             <-1, -1, 1>, <-1, 1, -1>, <1, -1, -1>, <-1, -1, -1> }
    #local Start = Middle + vnormalize(Dir[D]) * Reach + <0.0123, 0.0234, 0.0345> * vlength(Size);
    #local N = <0, 0, 0>;
    #local Hit = trace(Object, Start, Middle - Start, N);
    #debug concat(Name, " hit ", vstr(3, Hit, " ", 0, Digits), " normal ", vstr(3, N, " ", 0, Digits), "\n")
  #end
#end
#macro Show(Label, Value) #debug concat(Label, " ", Value, "\n") #end

// Interfaces to trace() and the extents.
#declare Ball = sphere { <1, 2, 3>, 1.5 }
#declare Point = <0, 0, 0>;
#declare Normal = <0, 0, 0>;
Show("Isect hit", str(Isect(<1, 2, -5>, z, Ball, Point), 0, 0))
Show("Isect point", vstr(3, Point, " ", 0, 4))
Show("Isect miss", str(Isect(<10, 2, -5>, z, Ball, Point), 0, 0))
Show("Isect point after miss", vstr(3, Point, " ", 0, 4))
Show("IsectN hit", str(IsectN(<0, 0, 0>, <1, 2, 3>, Ball, Point, Normal), 0, 0))
Show("IsectN point", vstr(3, Point, " ", 0, 4))
Show("IsectN normal", vstr(3, Normal, " ", 0, 4))
#declare Low = <0, 0, 0>;
#declare High = <0, 0, 0>;
Extents(Ball, Low, High)
Show("Extents", concat(vstr(3, Low, " ", 0, 4), " / ", vstr(3, High, " ", 0, 4)))
Probe("Center_Object x", object { Center_Object(Ball, x) })
Probe("Center_Object xyz", object { Center_Object(Ball, <1, 1, 1>) })
Probe("Align_Object", object { Align_Object(Ball, <-1, 1, 0>, <5, 5, 5>) })
Show("Align_Left", str(Align_Left, 0, 0))
Show("Align_Right", str(Align_Right, 0, 0))
Show("Align_Center", str(Align_Center, 0, 0))

// Shapes.
#declare Clip = box { <-3, -3, -3>, <3, 3, 3> }
Probe("Wedge 60", intersection { object { Wedge(60) } object { Clip } })
Probe("Wedge 150", intersection { object { Wedge(150) } object { Clip } })
Probe("Wedge 270", intersection { object { Wedge(270) } object { Clip } })
Probe("Spheroid", object { Spheroid(<1, -1, 2>, <2, 0.5, 1>) })
Probe("Supertorus", object { Supertorus(2, 0.5, 0.5, 0.3, 0.001, 5) })
Probe("Supertorus evaluate", object { Supertorus(1.5, 0.4, 1, 1, 0.01, 0) })
Probe("Supercone", object { Supercone(<0, 0, 0>, 1, 0.5, <0, 2, 0>, 0.25, 1.5) })
Probe("Supercone slanted", object { Supercone(<1, 0, 0>, 1, 0.5, <0, 1, 2>, 0.5, 1) })
Probe("Connect_Spheres", object { Connect_Spheres(<0, 0, 0>, 1, <3, 1, 0>, 0.4) })
Probe("Wire_Box_Union", object { Wire_Box_Union(<-1, -1, -1>, <1, 2, 3>, 0.1) })
Probe("Wire_Box_Merge", object { Wire_Box_Merge(<1, 2, 3>, <-1, -1, -1>, 0.2) })
Probe("Wire_Box", object { Wire_Box(<0, 0, 0>, <2, 1, 1>, 0.05, 1) })
Probe("Round_Box_Union", object { Round_Box_Union(<-1, -1, -1>, <1, 2, 3>, 0.25) })
Probe("Round_Box_Merge", object { Round_Box_Merge(<1, 2, 3>, <-1, -1, -1>, 0.5) })
Probe("Round_Box", object { Round_Box(<0, 0, 0>, <2, 1, 1>, 0.1, 0) })
Probe("Round_Cylinder_Union", object { Round_Cylinder_Union(<0, 0, 0>, <0, 2, 0>, 1, 0.25) })
Probe("Round_Cylinder_Merge", object { Round_Cylinder_Merge(<1, 0, 0>, <2, 1, 3>, 0.5, 0.1) })
Probe("Round_Cylinder", object { Round_Cylinder(<0, 0, 0>, <0, 0, -2>, 0.7, 0.3, 1) })
Probe("Round_Cone_Union", object { Round_Cone_Union(<0, 0, 0>, 1, <0, 2, 0>, 0.5, 0.2) })
Probe("Round_Cone_Merge", object { Round_Cone_Merge(<1, 0, 0>, 0.4, <2, 1, 3>, 0.8, 0.1) })
Probe("Round_Cone", object { Round_Cone(<0, 0, 0>, 1, <0, 0, -2>, 1, 0.3, 1) })
Probe("Round_Cone2_Union", object { Round_Cone2_Union(<0, 0, 0>, 1, <0, 2, 0>, 0.5) })
Probe("Round_Cone2_Merge", object { Round_Cone2_Merge(<1, 0, 0>, 0.4, <2, 1, 3>, 0.8) })
Probe("Round_Cone2", object { Round_Cone2(<0, 0, 0>, 0.6, <3, 0, 0>, 0.6, 1) })
Probe("Round_Cone3_Union", object { Round_Cone3_Union(<0, 0, 0>, 1, <0, 2, 0>, 0.5) })
Probe("Round_Cone3_Merge", object { Round_Cone3_Merge(<1, 0, 0>, 0.4, <2, 1, 3>, 0.8) })
Probe("Round_Cone3", object { Round_Cone3(<0, 0, 0>, 0.6, <3, 0, 0>, 0.6, 1) })
ProbeSurface("Quad", mesh { Quad(<0, 0, 0>, <2, 0, 0>, <2, 1, 1>, <0, 1, 0.5>) })
ProbeSurface("Smooth_Quad", mesh { Smooth_Quad(<0, 0, 0>, y, <2, 0, 0>, <0, 1, 1>, <2, 1, 1>, z, <0, 1, 0.5>, <1, 1, 1>) })

// Text (POV-Ray's fonts; Text_Space is left out: ours can differ by a few hundredths).
// The bevel depth is chosen so that no grid point lies in the last 0.5% of the bevelled
// slice, where POV-Ray's bevel already stops and ours does not (see the README).
Show("Text_Width Hello", str(Text_Width("timrom.ttf", "Hello", 1, 0), 0, 5))
Show("Text_Width spaced", str(Text_Width("timrom.ttf", "Ab c ", 2, 0.1), 0, 5))
ProbeText("Circle_Text L", Circle_Text("timrom.ttf", "POV-Ray", 1, 0, 0.2, 3, 0, Align_Left, 30))
ProbeText("Circle_Text R", Circle_Text("crystal.ttf", "AVAV", 0.5, 0.1, 0.1, 1.5, 0, Align_Right, 0))
ProbeText("Circle_Text inv", Circle_Text("timrom.ttf", "Wave", 1, 0.05, 0.3, 2, 1, Align_Center, -90))
ProbeText("Bevelled_Text", Bevelled_Text("timrom.ttf", "Ab", 5, 40, 0.06, 0.25, 0, 0))
ProbeText("Bevelled merged", Bevelled_Text("cyrvetic.ttf", "Go", 8, 30, 0.1, 0.3, <0.1, 0, 2>, 1))

// Height-field meshes, made directly and through a written file.
#declare Bumps = function { 0.1 + 0.5 * x * x + 0.25 * y + 0.125 * z * x }
#declare Waves = function { 0.5 + 0.3 * sin(x * 7) * cos(z * 5 + y) }
ProbeSurface("HF_Square", HF_Square(Bumps, 0, 0, <6, 5>, 1, "", <0, 0.5, 0>, <2, 1.5, 1>))
ProbeSurface("HF_Square uv", HF_Square(Waves, 1, 1, <9, 7>, 0, "", <-1, 0, -1>, <1, 0.5, 1>))
ProbeSurface("HF_Sphere", HF_Sphere(Bumps, 0, 1, <12, 9>, 1, "", <1, 2, 3>, 2, 0.5))
ProbeSurface("HF_Cylinder", HF_Cylinder(Waves, 1, 0, <10, 6>, 1, "", <0, 0, 0>, <1, 2, 3>, 1, 0.5))
ProbeSurface("HF_Torus", HF_Torus(Waves, 0, 1, <16, 8>, 1, "", 2, 0.5, 0.25))
HF_Torus(Bumps, 1, 1, <8, 6>, 1, "hf_torus.inc", 2, 0.5, 0.25)
ProbeSurface("HF_Torus file", object { #include "hf_torus.inc" })
