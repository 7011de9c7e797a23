#declare A = 1 + ;
#declare B = (2 * 3;
#declare C = <1, 2, 3;
sphere { <0, 0, 0>, 1 }
#declare D = max(1, 2;
camera { location <0, 1, -3> look_at 0 }
