#!/usr/bin/env python3
"""Measures colour maps as facts: samples each named color_map through a gradient pigment
with Debian's povray, finds the positions where the colours change course (the map's
entries) and where they jump, and prints each map as a list of entries.

Usage: measure-maps.py INCLUDE_DIR OUTPUT FILE:MAP [FILE:MAP ...]
Writes OUTPUT with lines "FILE MAP POSITION R G B F T"; at a jump the same position has
two lines, the colour just before it first.
"""
import os
import subprocess
import sys
import tempfile

STEP = 0.0005          # first pass: the map sampled every STEP
FINE = 1e-6            # each side of a jump, and the end of the map, sampled this far off
                       # and twice as far, and the colour right at the jump extrapolated
TOLERANCE = 2e-5       # a bend or a jump smaller than this is rounding noise


def run(include_dir, lines):
    """Runs a probe made of `lines` with the include files of include_dir; returns its
    #debug output as a list of lines."""
    with tempfile.TemporaryDirectory() as work:
        for name in os.listdir(include_dir):
            if name.endswith(('.inc', '.map')):
                os.symlink(os.path.join(include_dir, name), os.path.join(work, name))
        open(os.path.join(work, 'empty.ini'), 'w').close()
        with open(os.path.join(work, 'probe.pov'), 'w') as probe:
            probe.write('#version 3.7;\n' + '\n'.join(lines) + '\n')
        env = dict(os.environ, POVINI=os.path.join(work, 'empty.ini'))
        subprocess.run(['povray', '+Iprobe.pov', '-D', '-F', '+W1', '+H1', '-GA',
                        '+GDdebug.txt', '+GFfatal.txt'], cwd=work, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        fatal = open(os.path.join(work, 'fatal.txt')).read()
        if fatal.strip():
            sys.exit('measure-maps.py: povray failed:\n' + fatal)
        return open(os.path.join(work, 'debug.txt')).read().splitlines()


def sampler(index, file, name):
    return [f'#include "{file}"',
            f'#declare S{index} = function {{ pigment {{ gradient x color_map {{ {name} }} }} }}']


# Each sample printed is numbered; its position is remembered here, because POV-Ray wraps
# #debug lines longer than 80 characters.
POSITIONS = []


def sample_lines(index, positions):
    out = []
    for t in positions:
        POSITIONS.append(t)
        out.append(f'#local C = S{index}({t!r}, 0, 0);')
        out.append(f'#debug concat("{index} {len(POSITIONS) - 1} ", str(C.red, 0, 8), " ", '
                   f'str(C.green, 0, 8), " ", str(C.blue, 0, 8), " ", str(C.filter, 0, 8), " ", '
                   f'str(C.transmit, 0, 8), "\\n")')
    return out


def parse(output):
    values = {}
    for line in output:
        parts = line.split()
        if len(parts) == 7:
            values[(int(parts[0]), POSITIONS[int(parts[1])])] = [float(p) for p in parts[2:]]
    return values


def main():
    include_dir, output = os.path.abspath(sys.argv[1]), sys.argv[2]
    maps = [m.split(":") for m in sys.argv[3:]]
    count = int(round(1 / STEP))
    grid = [k * STEP for k in range(count)] + [1 - FINE]
    lines = []
    for index, (file, name) in enumerate(maps):
        lines += sampler(index, file, name) + sample_lines(index, grid)
    first = parse(run(include_dir, lines))

    # Bends: where the slope on the left differs from the slope on the right, the
    # entry lies where the two lines meet.  Jumps: where one step changes far more than
    # its neighbours, the jump lies inside that step and is pinned down by bisection.
    bends, jumps = {}, {}
    for index in range(len(maps)):
        samples = [first[(index, t)] for t in grid]
        for k in range(1, count - 1):
            left = [b - a for a, b in zip(samples[k - 1], samples[k])]
            right = [b - a for a, b in zip(samples[k], samples[k + 1])]
            if max(abs(r - l) for l, r in zip(left, right)) > TOLERANCE:
                bends.setdefault(index, []).append(k)
    # A jump shows as two bends one step apart with a large step between them.
    entries = {}
    for index in range(len(maps)):
        samples = [first[(index, t)] for t in grid]
        found = []
        ks = bends.get(index, [])
        used = set()
        for k in ks:
            if k in used:
                continue
            if k + 1 in ks and k >= 1 and k + 2 <= count:
                step = [abs(b - a) for a, b in zip(samples[k], samples[k + 1])]
                before = [abs(b - a) for a, b in zip(samples[k - 1], samples[k])]
                after = [abs(b - a) for a, b in zip(samples[k + 1], samples[k + 2])] if k + 2 <= count else before
                if max(s - max(b, a) for s, b, a in zip(step, before, after)) > 10 * TOLERANCE:
                    jumps.setdefault(index, []).append(k)
                    used.update({k, k + 1})
                    continue
            # The two lines through samples k-1, k and k+1, k+2 meet at the entry.
            if k >= 1 and k + 2 <= count:
                best = None
                for c in range(5):
                    s1 = (samples[k][c] - samples[k - 1][c]) / STEP
                    s2 = (samples[k + 2][c] - samples[k + 1][c]) / STEP
                    if abs(s1 - s2) > TOLERANCE / STEP:
                        # s1 (t - t_k) + v_k = s2 (t - t_{k+1}) + v_{k+1}
                        t = (samples[k + 1][c] - samples[k][c] - s2 * grid[k + 1] + s1 * grid[k]) / (s1 - s2)
                        best = t
                        break
                if best is not None:
                    # Entries sit on round positions (thousandths, or 255ths in the
                    # palettes made from images); snap to one when within the noise.
                    for grid_size in (1000, 255):
                        if abs(best * grid_size - round(best * grid_size)) < 3e-6 * grid_size:
                            best = round(best * grid_size) / grid_size
                            break
                    found.append(round(best, 6))
                    used.update({k, k + 1})
        entries[index] = sorted(set(found))

    # Second pass: the colour at every entry, and both sides of every jump, found by
    # bisecting the step that holds it.
    lo = {i: {k: grid[k] for k in ks} for i, ks in jumps.items()}
    hi = {i: {k: grid[k + 1] for k in ks} for i, ks in jumps.items()}
    for _ in range(20):
        lines = []
        for index, ks in jumps.items():
            lines += sampler(index, *maps[index])
            lines += sample_lines(index, [(lo[index][k] + hi[index][k]) / 2 for k in ks])
        mids = parse(run(include_dir, lines))
        for index, ks in jumps.items():
            samples = [first[(index, t)] for t in grid]
            for k in ks:
                mid = (lo[index][k] + hi[index][k]) / 2
                # Which side's straight line the middle sample lies on.
                on_left = [v + (v - u) / STEP * (mid - grid[k]) for u, v in zip(samples[k - 1], samples[k])]
                on_right = [v - (w - v) / STEP * (grid[k + 1] - mid) for v, w in zip(samples[k + 1], samples[k + 2])]
                got = mids[(index, mid)]
                if sum(abs(a - b) for a, b in zip(got, on_left)) < sum(abs(a - b) for a, b in zip(got, on_right)):
                    lo[index][k] = mid
                else:
                    hi[index][k] = mid
    lines = []
    wanted = {}
    for index in range(len(maps)):
        lines += sampler(index, *maps[index])
        # (position to print, position to sample) for the ends, the bends and both sides
        # of every jump, in order along the map.
        rows = [(0.0, 0.0, 0.0)] + [(t, t, t) for t in entries[index]] + [(1.0, 1 - FINE, 1 - 2 * FINE)]
        for k in jumps.get(index, []):
            position = round((lo[index][k] + hi[index][k]) / 2, 6)
            rows += [(position, position - FINE, position - 2 * FINE),
                     (position, position + FINE, position + 2 * FINE)]
        rows.sort(key=lambda row: row[1])
        wanted[index] = rows
        lines += sample_lines(index, [near for _, near, _ in rows] + [far for _, near, far in rows if far != near])
    final = parse(run(include_dir, lines))
    with open(output, 'w') as out:
        out.write('# Colour maps measured by analysis/stdinc/measure-maps.py: file map position r g b f t\n')
        for index, (file, name) in enumerate(maps):
            for position, near, far in wanted[index]:
                colour = final[(index, near)]
                if far != near:
                    # The segment is straight, so step back to the entry along it.
                    colour = [2 * a - b for a, b in zip(colour, final[(index, far)])]
                out.write(f'{file} {name} {position:.6f} ' + ' '.join(f'{c:.6f}' for c in colour) + '\n')


main()
