#!/usr/bin/env python3
"""docs/architecture.md is the map of the code: it names every file of common/ (by its name
in backticks, `quad_set` for quad_set.hpp and quad_set.cpp), every folder of tests/ (as
`tests/NAME/`) and shows docs/figures/layers.svg, which must be what
scripts/make-layers-figure writes from common/CMakeLists.txt today.

  python3 tests/docs/architecture_test.py ROOT
"""

import os
import re
import subprocess
import sys


def problems(root):
    page = open(os.path.join(root, "docs", "architecture.md"), encoding="utf-8").read()
    prose = re.sub(r"^```.*?^```", "", page, flags=re.M | re.S)  # fenced blocks pair no backticks
    named = set(re.findall(r"`([^`\n]+)`", prose))
    found = []
    common = os.path.join(root, "common")
    for layer in sorted(os.listdir(common)):
        folder = os.path.join(common, layer)
        if not os.path.isdir(folder):
            continue
        if f"{layer}/" not in named:
            found.append(f"common/{layer}/: the layer is not named as `{layer}/`")
        for f in sorted(os.listdir(folder)):
            stem = os.path.splitext(f)[0]
            if stem not in named and f not in named:
                found.append(f"common/{layer}/{f}: not named (`{stem}`)")
    tests = os.path.join(root, "tests")
    for f in sorted(os.listdir(tests)):
        if os.path.isdir(os.path.join(tests, f)) and not f.startswith(("_", ".")):
            if not re.search(rf"tests/{re.escape(f)}/", page):
                found.append(f"tests/{f}/: not named")
    if "figures/layers.svg" not in page:
        found.append("the page does not show figures/layers.svg")
    figure = os.path.join(root, "docs", "figures", "layers.svg")
    made = subprocess.run([sys.executable, os.path.join(root, "scripts", "make-layers-figure"),
                           "--print"], capture_output=True, text=True, check=True).stdout
    if not os.path.isfile(figure) or open(figure, encoding="utf-8").read() != made:
        found.append("docs/figures/layers.svg is not what scripts/make-layers-figure writes "
                     "(run it)")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(
        os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    found = problems(root)
    for line in found:
        print(line)
    if found:
        return 1
    print("docs/architecture.md names every file of common/ and every folder of tests/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
