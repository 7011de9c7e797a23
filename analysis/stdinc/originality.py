#!/usr/bin/env python3
"""Checks that our include files are our own work: for each of our files it looks for runs
of tokens, and runs of numbers, that also occur in POV-Ray's file of the same name, and
prints how much of our file such runs cover and on which of OUR lines they are.  It never
prints POV-Ray's text, so it can be run by someone writing these files without showing them
anything of POV-Ray's.

Usage: originality.py [--lines] [FILE...]   (default: every .inc of ours that POV-Ray also has)
POVRAY_INCLUDE_DIR overrides /usr/share/povray-3.7/include.

Comments are ignored; numbers are compared by value (0.50 and .5 are the same number), and
`color`/`colour` and commas are dropped, so that a copy in another layout is still found.
Shared runs are expected where the interface fixes the text: macro headers with the
manual's parameter names, include guards, identifier names, and measured values (colour
identifiers, whose values are facts).  A long run inside a definition or a macro body, or a
long run of numbers, means the text follows POV-Ray's and should be rewritten.
"""
import os
import re
import sys

TOKEN_RUN = 12   # tokens in a row that count as a shared run
NUMBER_RUN = 5   # telling numbers (is_number) in a row that count as a shared run
TOKEN = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:[^"\\]|\\.)*"|#\s*[A-Za-z]+|(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?'
    r'|[A-Za-z_][A-Za-z0-9_]*|\S', re.S)
DROPPED = {'color', 'colour', ','}


def tokens(path):
    """(token, line) pairs without comments, numbers normalised to their value."""
    text = open(path, errors='replace').read()
    found = []
    for match in TOKEN.finditer(text):
        token = match.group(0)
        if token.startswith(('//', '/*')) or token in DROPPED:
            continue
        if token[0].isdigit() or token[0] == '.' and len(token) > 1:
            token = repr(float(token))
        elif token.startswith('#'):
            token = '#' + token[1:].strip()
        found.append((token, text.count('\n', 0, match.start()) + 1))
    return found


def covered(ours, theirs, run):
    """Indices of `ours` inside a run of `run` items that also occurs in `theirs`."""
    grams = {tuple(theirs[i:i + run]) for i in range(len(theirs) - run + 1)}
    hit = set()
    for i in range(len(ours) - run + 1):
        if tuple(ours[i:i + run]) in grams:
            hit.update(range(i, i + run))
    return hit


def line_ranges(lines):
    ranges, start, previous = [], None, None
    for line in sorted(set(lines)):
        if start is None:
            start = previous = line
        elif line <= previous + 1:
            previous = line
        else:
            ranges.append((start, previous))
            start = previous = line
    if start is not None:
        ranges.append((start, previous))
    return ', '.join(f'{a}' if a == b else f'{a}-{b}' for a, b in ranges)


def is_number(token):
    """A number that says something: small whole numbers and halves are everywhere."""
    if not (token[0].isdigit() or token.startswith('-') and token[1:2].isdigit()):
        return False
    value = abs(float(token))
    return not (value <= 10 and value * 2 == int(value * 2))


def main():
    args = sys.argv[1:]
    show_lines = '--lines' in args
    args = [a for a in args if a != '--lines']
    here = os.path.dirname(os.path.abspath(__file__))
    std = os.environ.get('POVRAY_INCLUDE_DIR', '/usr/share/povray-3.7/include')
    names = args or sorted(f for f in os.listdir(here)
                           if f.endswith('.inc') and os.path.exists(os.path.join(std, f)))
    print(f"{'file':16} {'tokens':>6} {'in runs':>7} {'numbers':>7} {'in runs':>7}")
    for name in names:
        name = os.path.basename(name)
        ours = tokens(os.path.join(here, name))
        theirs = tokens(os.path.join(std, name))
        token_hits = covered([t for t, _ in ours], [t for t, _ in theirs], TOKEN_RUN)
        our_numbers = [(t, line) for t, line in ours if is_number(t)]
        number_hits = covered([t for t, _ in our_numbers],
                              [t for t, _ in theirs if is_number(t)], NUMBER_RUN)
        print(f"{name:16} {len(ours):6} {100 * len(token_hits) / max(1, len(ours)):6.1f}%"
              f" {len(our_numbers):7} {100 * len(number_hits) / max(1, len(our_numbers)):6.1f}%")
        if show_lines:
            lines = [ours[i][1] for i in token_hits] + [our_numbers[i][1] for i in number_hits]
            if lines:
                print(f"    our lines: {line_ranges(lines)}")


main()
