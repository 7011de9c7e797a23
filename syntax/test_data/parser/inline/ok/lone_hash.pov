#Macro(1)
camera { look_at 0 # }
