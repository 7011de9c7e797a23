color_map { [0 color Red] [0.5, 0.7 rgb 1 rgb 0] [1 Blue] }
