#!/usr/bin/env python3
"""Checks every #include "..." of the source tree against the layer order.

usage: check_layers.py SOURCE_DIR LAYER [LAYER ...]   (lowest layer first)

A file in layer L may include headers of L and of the layers before it, and
nothing from a folder of the tree that is not a layer (headers the build
generates are not in the tree). tests/ and bench/ may include any layer. Prints each violation as FILE:LINE: ... and exits 1 if there is one.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def main() -> int:
    root = pathlib.Path(sys.argv[1])
    layers = sys.argv[2:]
    rank = {layer: i for i, layer in enumerate(layers)}
    problems, checked = [], 0
    for layer in layers:
        for path in sorted((root / layer).rglob("*")):
            if path.suffix not in (".hpp", ".cpp", ".h"):
                continue
            for number, line in enumerate(path.read_text().splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                checked += 1
                target = match.group(1).split("/")[0]
                where = f"{path.relative_to(root)}:{number}"
                if target not in rank:
                    # A folder of the tree that is not a layer (tests/, bench/)
                    # is out of bounds; a header the build generates is not.
                    if (root / target).exists():
                        problems.append(f'{where}: includes "{match.group(1)}", which is in no layer')
                elif rank[target] > rank[layer]:
                    problems.append(f'{where}: layer {layer} includes "{match.group(1)}" of layer {target}, '
                                    f"which comes after it ({' <- '.join(layers)})")
    for p in problems:
        print(p)
    print(f"{checked} includes checked in {len(layers)} layers: {len(problems)} against the order")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
