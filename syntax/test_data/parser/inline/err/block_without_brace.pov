#declare T = texture pigment { Red } };
