#version 3.7;
#debug concat("image_width = ", str(image_width, 0, 6), "\n")
#debug concat("image_height = ", str(image_height, 0, 6), "\n")
#debug concat("image_width/image_height = ", str(image_width/image_height, 0, 6), "\n")
