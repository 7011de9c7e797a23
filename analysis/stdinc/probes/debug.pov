#version 3.7;
// debug.inc's messages, and the include stack it switches on.
#include "debug.inc"
Debug_Message("default state\n")
Set_Debug(true)
Debug_Message("on\n")
Set_Debug(false)
Debug_Message("off\n")
Debug(true, "Debug true\n")
Debug(false, "Debug false\n")
Set_Debug(true)
Debug(false, "Debug false while on\n")
Warning(false, "no warning")
Error(false, "no error")
Debug_Inc_Stack()
#include "stdinc.inc"
#include "colors.inc"
#include "arrays.inc"
#include "rad_def.inc"
