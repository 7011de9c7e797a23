#version 3.7;
#debug concat("strcmp(\"abc\", \"abd\") = ", str(strcmp("abc", "abd"), 0, 0), "\n")
#debug concat("strcmp(\"b\", \"abd\") = ", str(strcmp("b", "abd"), 0, 0), "\n")
#debug concat("strcmp(\"abc\", \"abc\") = ", str(strcmp("abc", "abc"), 0, 0), "\n")
#debug concat("strcmp(\"abcz\", \"abc\") = ", str(strcmp("abcz", "abc"), 0, 0), "\n")
#debug concat("strcmp(\"A\", \"a\") = ", str(strcmp("A", "a"), 0, 0), "\n")
#debug concat("strcmp(\"\", \"x\") = ", str(strcmp("", "x"), 0, 0), "\n")
