#version 3.7;
#debug concat("!0 = ", str(!0, 0, 0), "\n")
#debug concat("!1 = ", str(!1, 0, 0), "\n")
#debug concat("!!5 = ", str(!!5, 0, 0), "\n")
#debug concat("!-1 = ", str(!-1, 0, 0), "\n")
#debug concat("!0.5 = ", str(!0.5, 0, 0), "\n")
