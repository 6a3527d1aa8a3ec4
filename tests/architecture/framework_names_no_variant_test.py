"""The framework never asks which method or strategy runs (issue 37): a method or strategy is
added by adding its files under variants/, and no framework file names one.

Every registered name (`lpvlab list --json`: LPV's strategies and the indirect methods, LPV among
them) is looked for as a string literal in the code of framework/ (comments left out), and every
comparison of a name() with anything. framework/many_lights and framework/radiosity are left
out: they are the libraries the many-light and radiosity methods share, and name their own
techniques (a VPL method's "imperfect_shadow_maps" visibility).

The one name the framework must state is the default of [indirect] method, "lpv", where the
experiment is read; it is allowed there alone.

    framework_names_no_variant_test.py BUILD_DIR/lpvlab
"""
import json
import os
import re
import subprocess
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
METHOD_LIBRARIES = {"many_lights", "radiosity"}
ALLOWED = {("framework/experiment/experiment.cpp", "lpv")}  # [indirect] method's default


def code_without_comments(text):
    """C++ text with // and /* */ comments blanked, string literals kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = n if end < 0 else end + 2
        elif text[i] == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def framework_files():
    root = os.path.join(SOURCE, "framework")
    for module in sorted(os.listdir(root)):
        if module in METHOD_LIBRARIES:
            continue
        for directory, _, files in os.walk(os.path.join(root, module)):
            for name in sorted(files):
                if name.endswith((".cpp", ".h")):
                    path = os.path.join(directory, name)
                    yield os.path.relpath(path, SOURCE), path


def main():
    listing = json.loads(subprocess.run([sys.argv[1], "list", "--json"], check=True,
                                        capture_output=True, text=True).stdout)
    names = {s["name"] for s in listing["strategies"]} | {m["name"] for m in listing["methods"]}
    names.discard("none")  # "none" is every option's word for nothing, not only a strategy's
    assert "lpv" in names and "radiosity" in names and "rsm_vpl" in names, sorted(names)
    found = []
    checked = 0
    for relative, path in framework_files():
        checked += 1
        code = code_without_comments(open(path, encoding="utf-8").read())
        for literal in re.findall(r'"([a-z0-9_]+)"', code):
            if literal in names and (relative, literal) not in ALLOWED:
                found.append(f"{relative}: names \"{literal}\"")
        for match in re.finditer(r"(?:->|\.)name\(\)\s*[!=]=|[!=]=\s*[\w.>-]*(?:->|\.)name\(\)", code):
            line = code.count("\n", 0, match.start()) + 1
            found.append(f"{relative}:{line}: compares a name() (a branch on which variant runs)")
    print(f"{checked} framework files checked against {len(names)} registered names")
    for line in found:
        print("FAIL:", line)
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
