#!/usr/bin/env python3
"""The reflect/refract calls of piglit .shader_test files, as `snell eval` lines.

A piglit test binds the built-in's arguments to uniforms, sets them in its
[test] section and draws (or dispatches) once per vector. The calls are read
from the shader text (`refract(arg0, arg1, arg2)`), the uniform values are
tracked through the [test] section, and each `draw`/`compute` command gives
one vector. A file whose call arguments are not uniforms (constants folded
by the compiler) gives no vectors.

Usage: shader_test_vectors.py FILE...   (JSON Lines on stdout)
Exit 2, with FILE:LINE, on a file this reader cannot follow.
"""
import json
import re
import sys

CALL = re.compile(r"\b(reflect|refract)\s*\(\s*(\w+)\s*,\s*(\w+)\s*(?:,\s*(\w+)\s*)?\)")
UNIFORM = re.compile(r"^uniform\s+(float|vec[234])\s+(\w+)\s+(.*)$")
DRAW = re.compile(r"^(draw\s|compute\s)")
WIDTHS = {"float": 1, "vec2": 2, "vec3": 3, "vec4": 4}


class ParseError(Exception):
    """A line this reader cannot follow: FILE:LINE and what is wrong."""


def _number(text, where):
    try:
        return float(text)
    except ValueError:
        raise ParseError(f"{where}: '{text}' is not a number; uniform values must be numbers")


def vectors(text, path="<text>"):
    """The calls in `text` (a .shader_test), each a dict: fn, I, N (and eta)
    ready for `snell eval`, plus `where` (FILE:LINE of its draw command)."""
    lines = text.splitlines()
    try:
        test_start = next(i for i, line in enumerate(lines) if line.strip() == "[test]")
    except StopIteration:
        raise ParseError(f"{path}:1: no [test] section; is this a piglit .shader_test file?")
    calls = {m.group(0): m for m in CALL.finditer("\n".join(lines[:test_start]))}
    if len(calls) > 1:
        raise ParseError(f"{path}:1: {len(calls)} different reflect/refract calls; "
                         "this reader follows files with one")
    if not calls:
        return []
    call = next(iter(calls.values()))
    fn, names = call.group(1), [n for n in call.groups()[1:] if n]
    if fn == "refract" and len(names) != 3 or fn == "reflect" and len(names) != 2:
        raise ParseError(f"{path}:1: {fn} called with {len(names)} arguments")
    values = {}
    found = []
    for number, raw in enumerate(lines[test_start + 1:], start=test_start + 2):
        line = raw.split("#", 1)[0].strip()
        where = f"{path}:{number}"
        match = UNIFORM.match(line)
        if match:
            kind, name, rest = match.groups()
            numbers = [_number(x, where) for x in rest.split()]
            if len(numbers) != WIDTHS[kind]:
                raise ParseError(f"{where}: {kind} {name} needs {WIDTHS[kind]} numbers, "
                                 f"got {len(numbers)}")
            values[name] = numbers
        elif DRAW.match(line):
            if not all(name in values for name in names):
                # Arguments that are not uniforms set here: a constant call.
                continue
            I, N = values[names[0]], values[names[1]]
            if len(I) != len(N):
                raise ParseError(f"{where}: {names[0]} has {len(I)} components and "
                                 f"{names[1]} has {len(N)}")
            vector = {"fn": fn, "I": I, "N": N}
            if fn == "refract":
                if len(values[names[2]]) != 1:
                    raise ParseError(f"{where}: eta ({names[2]}) must be a float")
                vector["eta"] = values[names[2]][0]
            vector["where"] = where
            found.append(vector)
    return found


def eval_line(vector):
    """The `snell eval` input line for one vector (without its `where`)."""
    return json.dumps({k: v for k, v in vector.items() if k != "where"})


def main(paths):
    if not paths:
        print(__doc__.strip().splitlines()[-2], file=sys.stderr)
        return 2
    try:
        for path in paths:
            with open(path, encoding="utf-8") as file:
                for vector in vectors(file.read(), path):
                    print(eval_line(vector))
    except OSError as error:
        print(f"{error.filename}: cannot read ({error.strerror})", file=sys.stderr)
        return 2
    except ParseError as error:
        print(error, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
