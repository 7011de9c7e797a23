#declare (A, B, C) = (1, 2, 3);
#local (, Second) = Pair();
