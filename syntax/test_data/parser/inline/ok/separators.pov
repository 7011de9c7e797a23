#version 3.7; ; sphere { <0, 0, 0>, 1 };
