#!/usr/bin/env python3
"""Compiles a Typst document with the real Typst compiler (the `typst` Python binding) and
reports errors the way `typst compile` does: `error: MESSAGE`, where, and hints.

    typst-compile.py INPUT.typ [OUTPUT.pdf|.png|.svg] [--root DIR] [--package-path DIR]
                     [--input KEY=VALUE]... [--query SELECTOR] [--json-errors] [--timings]

With --query, prints the JSON of the `value` field of the metadata the selector finds
instead of writing an output file. Exit status: 0 done, 1 compile error, 2 usage error.
"""

import argparse
import json
import sys
import time


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output", nargs="?")
    parser.add_argument("--root", default=".")
    parser.add_argument("--package-path", default=None)
    parser.add_argument("--input", dest="sys_inputs", action="append", default=[], metavar="KEY=VALUE")
    parser.add_argument("--query", default=None, metavar="SELECTOR")
    parser.add_argument("--ppi", type=float, default=None)
    parser.add_argument(
        "--timings",
        action="store_true",
        help="print the compile's wall and CPU seconds (every thread of the process) on stderr",
    )
    parser.add_argument(
        "--json-errors",
        action="store_true",
        help="report a compile error as JSON {message, hints, diagnostic} on stderr",
    )
    args = parser.parse_args()
    if args.output is None and args.query is None:
        parser.error("give an OUTPUT file or --query")

    import typst  # Imported late so that --help works without the binding.

    sys_inputs = {}
    for pair in args.sys_inputs:
        key, sep, value = pair.partition("=")
        if not sep:
            parser.error(f"--input wants KEY=VALUE, got {pair!r}")
        sys_inputs[key] = value

    compiler = typst.Compiler(
        input=args.input,
        root=args.root,
        sys_inputs=sys_inputs,
        package_path=args.package_path,
    )
    started = time.perf_counter()
    cpu_started = time.process_time()
    try:
        if args.query is not None:
            found = compiler.query(args.query, field="value", one=True)
            print(found)
        else:
            compiler.compile(output=args.output, ppi=args.ppi)
    except (typst.TypstError, RuntimeError) as error:
        # Queries fail with a plain RuntimeError when the selector finds nothing.
        message = getattr(error, "message", str(error))
        if args.json_errors:
            report = {
                "message": message,
                "hints": getattr(error, "hints", []),
                "diagnostic": getattr(error, "diagnostic", f"error: {message}"),
            }
            print(json.dumps(report), file=sys.stderr)
        else:
            print(getattr(error, "diagnostic", f"error: {message}"), file=sys.stderr)
        return 1
    if args.timings:
        wall = time.perf_counter() - started
        cpu = time.process_time() - cpu_started
        print(f"compiled {args.input} in {wall:.3f} s, {cpu:.3f} CPU s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
