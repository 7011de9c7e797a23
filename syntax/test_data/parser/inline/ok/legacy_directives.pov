declare R = 1;
include "colors.inc"
version 3.1;
default { finish { ambient 0.2 } }
