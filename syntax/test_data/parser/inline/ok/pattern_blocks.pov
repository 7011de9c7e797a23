#declare F = function { pattern { checker } }
pigment { image_map { pattern 100, 100 { gradient x } } }
