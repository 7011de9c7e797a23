#version 3.7;
#debug concat("concat(concat(\"a\", \"b\"), concat(\"c\", concat(\"d\", \"e\"))) = [", concat(concat("a", "b"), concat("c", concat("d", "e"))), "]\n")
