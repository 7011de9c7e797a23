#debug concat("version = ", str(version, 0, 2), "\n")
