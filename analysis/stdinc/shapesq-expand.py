#!/usr/bin/env python3
"""Writes shapesq.inc's surfaces as `poly` objects from their equations.

Each surface is given below as an equation in x, y and z (the manual's, section 3.4.9.1.21,
where it gives one, and our own choice where it does not); sympy expands it and the
coefficients are listed in the order `poly` takes them: terms x^i y^j z^k of every total
degree up to the order, by falling i, then falling j, then falling k.  The points where the
polynomial is negative are inside; three equations are negated below so that the same
side is inside as in POV-Ray's (Bicorn, Devils_Curve and Quartic_Loop_1, measured with
probes/shapesq.pov).

Usage: shapesq-expand.py > /dev/null   (rewrites shapesq.inc beside this script; needs
python3-sympy)
"""
import os

import sympy

x, y, z = sympy.symbols('x y z')

# name, comment, order, polynomial (= 0 on the surface, < 0 inside), what follows the list;
# an order of None makes the name another name of the surface given as the polynomial
SURFACES = [
    ('Bicorn', 'The top of a paraboloid closed below by another.',
     4, -(y**2 - (x**2 + z**2) * y**2 - (x**2 + z**2 + 2 * y - 1)**2), ''),
    ('Crossed_Trough', 'Four pieces sweeping up from the x-z plane: y = x^2 z^2.',
     4, x**2 * z**2 - y, ''),
    ('Cubic_Cylinder', 'A drop leaving water: the curve y = x^2 (x + 1) / 2 swept around the x axis.',
     3, y**2 + z**2 - sympy.Rational(1, 2) * (x**3 + x**2), ''),
    ('Cubic_Saddle_1', 'A cubic saddle: z = x^3 - y^3.',
     3, x**3 - y**3 - z, ''),
    ('Devils_Curve', 'A devil\'s curve in space: two hyperboloid-like halves pinched in the middle\n'
     '// around two teardrop-shaped holes.',
     4, -(x**4 + 2 * x**2 * z**2 - sympy.Rational(36, 100) * x**2 - y**4 + sympy.Rational(1, 4) * y**2 + z**4), ''),
    ('Folium', 'A folium turned about the x axis.',
     3, 2 * x**2 - 3 * x * y**2 - 3 * x * z**2 + y**2 + z**2, ''),
    ('Glob_5', 'A teardrop: y^2 + z^2 = (x^5 + x^4) / 2.',
     5, y**2 + z**2 - sympy.Rational(1, 2) * (x**5 + x**4), ''),
    ('Twin_Glob', 'A lemniscate with teardrop lobes (our own equation, the manual gives none):\n'
     '// y^2 + z^2 = x^4 - x^6.',
     6, y**2 + z**2 - x**4 + x**6, ''),
    ('Helix', 'The manual\'s approximation of the helix z = atan(y / x): x (z - z^3 / 6) = y (1 + z^2 / 2),\n'
     '// scaled by 2 so that it turns 90 degrees between z = 0 and z = sqrt(2), and cut out by a\n'
     '// cylinder of radius 2 there.',
     4, -sympy.Rational(1, 6) * x * z**3 + x * z + sympy.Rational(1, 2) * y * z**2 - y,
     'scale 2\n  clipped_by { cylinder { 0, sqrt(2) * z, 2 } }\n  bounded_by { clipped_by }'),
    ('Helix_1', 'The same helix under its other name (POV-Ray\'s two are the same shape, as\n'
     '// probes/shapesq.pov shows).', None, 'Helix', ''),
    ('Hyperbolic_Torus_40_12', 'A circle swept along the arms of a hyperbola (major radius sqrt(40),\n'
     '// minor sqrt(12)).',
     4, x**4 + 2 * x**2 * y**2 - 2 * x**2 * z**2 - 104 * x**2 + y**4 - 2 * y**2 * z**2 + 56 * y**2
     + z**4 + 104 * z**2 + 784, ''),
    ('Lemniscate', 'The lemniscate of Gerono turned about the x axis: two teardrops point to point.',
     4, x**4 - x**2 + y**2 + z**2, ''),
    ('Quartic_Loop_1', 'A bumpy sheet on one side, a paraboloid with a bubble inside on the other.',
     4, -(-99 * x**4 + 40 * x**3 - 98 * x**2 * y**2 - 98 * x**2 * z**2 + 99 * x**2 + 40 * x * y**2
     + 40 * x * z**2 + y**4 + 2 * y**2 * z**2 - y**2 + z**4 - z**2), ''),
    ('Monkey_Saddle', 'Three parts up and three down, room for two legs and a tail: z = x^3 - 3 x y^2.',
     3, x**3 - 3 * x * y**2 - z, ''),
    ('Parabolic_Torus_40_12', 'A circle swept along a parabola (major radius sqrt(40), minor sqrt(12)).',
     4, x**4 + 2 * x**2 * y**2 - 2 * x**2 * z - 104 * x**2 + y**4 - 2 * y**2 * z + 56 * y**2 + z**2
     + 104 * z + 784, ''),
    ('Piriform', 'A kiss-shaped drop: the piriform x^4 - x^3 + y^2 = 0 turned about the x axis.',
     4, x**4 - x**3 + y**2 + z**2, ''),
    ('Quartic_Paraboloid', 'A quartic parabola with two bumps at the bottom, swept around.',
     4, sympy.Rational(1, 10) * x**4 - x**2 - y**2 - z**2 + sympy.Rational(9, 10), ''),
    ('Quartic_Cylinder', 'A tower pinched in the middle (our own equation, the manual gives none):\n'
     '// x^2 + z^2 = 0.04 + 0.3 y^4.',
     4, x**2 + z**2 - sympy.Rational(4, 100) - sympy.Rational(3, 10) * y**4, ''),
    ('Steiner_Surface', 'Steiner\'s Roman surface (our choice of its quartic form).',
     4, x**2 * y**2 + y**2 * z**2 + z**2 * x**2 + x * y * z, ''),
    ('Torus_40_12', 'A torus around the y axis, major radius sqrt(40), minor sqrt(12) (our choice of\n'
     '// axis).',
     4, (x**2 + y**2 + z**2 + 28)**2 - 160 * (x**2 + z**2), ''),
    ('Witch_Hat', 'The witch of Agnesi y = 1 / (1 + r^2) turned about the y axis (our choice of\n'
     '// scale).',
     3, y * (x**2 + z**2 + 1) - 1, ''),
    ('Sinsurf', 'A rough approximation of z = sin(2 pi x y): the first two terms of its Taylor\n'
     '// series (our choice); scale it by about <1, 1, 0.2>.',
     6, 2 * sympy.pi * x * y - sympy.Rational(4, 3) * sympy.pi**3 * x**3 * y**3 - z, ''),
]


def terms(order):
    for i in range(order, -1, -1):
        for j in range(order - i, -1, -1):
            for k in range(order - i - j, -1, -1):
                yield i, j, k


def number(value):
    value = float(value)
    text = f'{value:.10g}'
    return '0' if text == '-0' else text


def poly(order, expression):
    expanded = sympy.Poly(sympy.expand(expression), x, y, z)
    coefficients = {monomial: c for monomial, c in expanded.terms()}
    assert max(sum(m) for m in coefficients) <= order
    rows = []
    for i in range(order, -1, -1):
        row = [number(coefficients.get((i, j, k), 0)) for (a, j, k) in terms(order) if a == i]
        comma = ',' if i > 0 else ''
        rows.append(f'    {", ".join(row)}{comma}  // x^{i} terms')
    return '\n'.join(rows)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = ['''// shapesq.inc: cubic, quartic and higher algebraic surfaces (Povrayst's own version).
//
// How this file was made: names, descriptions and equations from POV-Ray 3.7's manual
// (section 3.4.9.1.21); where the manual gives no equation the surface is our own (said
// below).  analysis/stdinc/shapesq-expand.py expands each equation into the coefficients
// of a poly (the points where the polynomial is negative are inside) and writes this
// file.  Some of POV-Ray's surfaces are scaled or turned differently from the manual's
// equations; ours follow the equations (analysis/stdinc/probes/shapesq.pov compares the
// ones that agree).

#ifndef (ShapesQ_Inc_Temp)
#declare ShapesQ_Inc_Temp = version;
#version 3.7;
#ifdef (View_POV_Include_Stack)
  #debug "including shapesq.inc\\n"
#end
''']
    for name, comment, order, expression, after in SURFACES:
        out.append(f'// {comment}')
        if order is None:
            out.append(f'#declare {name} = object {{ {expression} }}\n')
            continue
        body = poly(order, expression)
        tail = f'\n  {after}' if after else ''
        out.append(f'#declare {name} = poly {{\n  {order},\n  <\n{body}\n  >{tail}\n}}\n')
    out.append('#version ShapesQ_Inc_Temp;\n#end')
    with open(os.path.join(here, 'shapesq.inc'), 'w') as f:
        f.write('\n'.join(out) + '\n')


main()
