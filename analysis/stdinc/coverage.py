#!/usr/bin/env python3
"""Compares the identifiers and macros that our include files declare at top level with
those of POV-Ray's files of the same name, and prints a table of what is provided and
what is missing.

Usage: coverage.py [POVRAY_INCLUDE_DIR]   (default /usr/share/povray-3.7/include)
Names that POV-Ray's files declare for their own use (include guards, loop counters,
the golds.inc helpers) are counted too, so "missing" lists everything a scene could
reach, documented or not.
"""
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
std = sys.argv[1] if len(sys.argv) > 1 else '/usr/share/povray-3.7/include'
TOKEN = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:[^"\\]|\\.)*"|#\s*[a-z]+|[A-Za-z_][A-Za-z0-9_]*|\S', re.S)
OPENING = {'if', 'ifdef', 'ifndef', 'while', 'for', 'switch', 'macro'}


def names(path):
    """Top-level declarations: not inside a macro, and not include guards."""
    tokens = [t for t in TOKEN.findall(open(path, errors='replace').read())
              if not t.startswith(('//', '/*'))]
    found, blocks = set(), []
    for index, token in enumerate(tokens):
        if not token.startswith('#'):
            continue
        directive = token[1:].strip()
        if directive in ('declare', 'macro') and 'macro' not in blocks:
            following = tokens[index + 1:index + 5]
            if following and following[0] == 'deprecated':
                following = following[1:]
                if following[0] == 'once':
                    following = following[1:]
                following = following[1:]
            name = following[0]
            if not re.search(r'_Inc_Temp$', name, re.I):
                found.add(name)
        if directive in OPENING:
            blocks.append(directive)
        elif directive == 'end' and blocks:
            blocks.pop()
    return found


ours = sorted(f for f in os.listdir(here) if f.endswith(('.inc', '.map')))
print(f"{'file':16} {'POV-Ray':>7} {'ours':>5} {'shared':>6}  missing")
for name in ours:
    theirs_path = os.path.join(std, name)
    mine = names(os.path.join(here, name))
    if not os.path.exists(theirs_path):
        print(f"{name:16} {'-':>7} {len(mine):5}")
        continue
    theirs = names(theirs_path)
    missing = sorted(theirs - mine)
    print(f"{name:16} {len(theirs):7} {len(mine):5} {len(theirs & mine):6}  {' '.join(missing) or '-'}")
absent = sorted(f for f in os.listdir(std) if f.endswith(('.inc', '.map')) and f not in ours)
print('not written:', ' '.join(absent))
