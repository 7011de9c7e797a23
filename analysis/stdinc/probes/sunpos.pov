#version 3.7;
// SunPos from sunpos.inc for a few dates, times and places, north and south.
#include "sunpos.inc"
#macro Sun_At(Y, M, D, H, Mi, Zone, Lat, Long)
  #local P = SunPos(Y, M, D, H, Mi, Zone, Lat, Long);
  #debug concat("direction ", vstr(3, vnormalize(P), " ", 0, 5), " length ", str(vlength(P), 0, 0), "\n")
  #debug concat("  Az ", str(Az, 0, 4), " Al ", str(Al, 0, 4), " same ", str(vlength(P - SolarPosition), 0, 0), "\n")
#end
Sun_At(2000, 6, 21, 12, 2, 0, 51.4667, 0)
Sun_At(2000, 12, 21, 9, 30, 15, 48.2, 16.37)
Sun_At(2013, 3, 20, 17, 45, -75, 40.7, -74)
Sun_At(1999, 8, 11, 11, 0, 15, -33.9, 18.4)
Sun_At(2024, 1, 1, 0, 30, 60, 35.7, 139.7)
Sun_At(1987, 10, 31, 23, 50, -120, 60, -150)
