#version 3.7;
#debug concat("(\"Z\" < \"a\") = ", str(("Z" < "a"), 0, 0), "\n")
#debug concat("(\"abc\" = \"ABC\") = ", str(("abc" = "ABC"), 0, 0), "\n")
