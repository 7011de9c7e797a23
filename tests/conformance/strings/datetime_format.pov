#version 3.7;
#debug concat("datetime(0, \"%Y/%m/%d\") = [", datetime(0, "%Y/%m/%d"), "]\n")
#debug concat("datetime(366.25, \"%j %H:%M\") = [", datetime(366.25, "%j %H:%M"), "]\n")
#debug concat("datetime(7000.5, \"%A %d %B %Y\") = [", datetime(7000.5, "%A %d %B %Y"), "]\n")
