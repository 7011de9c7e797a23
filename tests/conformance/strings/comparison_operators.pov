#version 3.7;
#debug concat("(\"abc\" < \"abd\") = ", str(("abc" < "abd"), 0, 0), "\n")
#debug concat("(\"abc\" <= \"abc\") = ", str(("abc" <= "abc"), 0, 0), "\n")
#debug concat("(\"abc\" = \"abc\") = ", str(("abc" = "abc"), 0, 0), "\n")
#debug concat("(\"b\" >= \"abc\") = ", str(("b" >= "abc"), 0, 0), "\n")
#debug concat("(\"b\" > \"abc\") = ", str(("b" > "abc"), 0, 0), "\n")
#debug concat("(\"a\" != \"a\") = ", str(("a" != "a"), 0, 0), "\n")
