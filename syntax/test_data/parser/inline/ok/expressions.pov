#declare A = -1 + 2*3 - 4/5;
#declare B = (A < 1 & A >= 0 | !A ? 1 : 2);
#declare C = <1, 2, 3>.x + V.y + D["key"] + Arr[1][2] + D.field;
#declare E = vlength(<1, 2, 3>) + max(1, 2, 3) + Macro(1, , "s");
#declare F = <(A > 1), 2>;
