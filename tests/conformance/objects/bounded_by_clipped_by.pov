#version 3.7;
#declare S = sphere { 0, 1 bounded_by { clipped_by } }
#debug concat("no clip: ", vstr(3, max_extent(S), ", ", 0, 2), "\n")
#declare T = sphere { 0, 1 bounded_by { clipped_by } clipped_by { box { -0.5, 0.5 } } }
#debug concat("clip after: ", vstr(3, max_extent(T), ", ", 0, 2), "\n")
#declare U = sphere { 0, 1 clipped_by { box { -0.5, 0.5 } } bounded_by { clipped_by } }
#debug concat("clip before: ", vstr(3, max_extent(U), ", ", 0, 2), "\n")
#declare V = sphere { 0, 1 bounded_by { box { -0.3, 0.3 } } clipped_by { bounded_by } }
#debug concat("clip by bounds: ", vstr(3, max_extent(V), ", ", 0, 2), "\n")
#declare W = sphere { 0, 1 bounded_by { box { -0.3, 0.3 } } translate x clipped_by { bounded_by } }
#debug concat("moved: ", vstr(3, min_extent(W), ", ", 0, 2), "\n")
