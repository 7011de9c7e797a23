#declare A = array[3] { 1, 2, 3 };
#declare M = array[2][2] { { 1, 2 }, { 3, 4 } };
#declare O = array mixed[2] { sphere { 0, 1 }, "two" };
#declare E = array[4];
