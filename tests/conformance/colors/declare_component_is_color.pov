#version 3.7;
#declare MyColor = rgb <0.75, 0.5, 0.75>;
#declare RedAmt = MyColor.red;
#debug concat("RedAmt = <", vstr(5, RedAmt, ", ", 0, 2), ">\n")
