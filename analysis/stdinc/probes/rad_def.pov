#version 3.7;
// Every preset of rad_def.inc inside a radiosity block; each announces itself.
#include "rad_def.inc"
#for (Setting, Radiosity_Default, Radiosity_IndoorHQ)
  global_settings { radiosity { Rad_Settings(Setting, on, off) } }
#end
