"""The code's shape (issue 37): small functions, no include cycles, documentation that names what
exists.

1. No function in framework/ or variants/ is longer than MAX_FUNCTION_LINES lines (the body from
   its opening to its closing brace). Functions are found by a brace scan of the code without
   comments and string literals: a `{` at namespace or class scope that follows a parameter list.
2. No include cycle among framework's units (a unit is X.h with X.cpp): unit A depends on unit B
   when A's header or source includes B's header. The allowed cycles are a module's internal
   helper whose header uses the module's public types while the module's source calls it.
3. Every repository path the README and docs/ name exists, and every link to a page's section
   (docs/<page>.md#<anchor>) from the code, the docs or the README finds that section.
4. Every registered strategy and method (`lpvlab list --json`) has its page,
   docs/variants/<name>.md: a variant is added with its files, its tests and its docs.
5. The conventions a cited research tool keeps: LICENSE, CITATION.cff naming the version that
   CMakeLists.txt builds (so a citation names what `lpvlab --version` prints), and CHANGELOG.md
   with that version or an Unreleased section.

    code_shape_test.py [BUILD_DIR/lpvlab]
"""
import functools
import glob
import json
import os
import re
import subprocess
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAX_FUNCTION_LINES = 80
# Internal helpers of one module: the helper's header includes the module's public header for its
# types, and the module's source includes the helper.
ALLOWED_CYCLES = [
    {"framework/gl/context", "framework/gl/context_backends"},
    {"framework/metrics/metrics", "framework/metrics/pixel_errors"},
    {"framework/reference/path_tracer", "framework/reference/integrator"},
]


def read(path):
    with open(os.path.join(SOURCE, path), encoding="utf-8") as f:
        return f.read()


def code_only(text):
    """C++ text with comments and string and character literals blanked; lines kept."""
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r'R"(\w*)\((.*?)\)\1"', lambda m: '""' + "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r'"(\\.|[^"\\\n])*"', '""', text)
    return re.sub(r"'(\\.|[^'\\\n])*'", "''", text)


PARAMETER_LIST_END = re.compile(r"\)\s*(const|noexcept|override|final|mutable|->\s*[\w:<>,\s*&]+|\s)*$")
CONTROL = re.compile(r"\b(if|for|while|switch|catch)\s*\(")


def functions(text):
    """(name, first line, lines) of each function defined outside another function."""
    scopes, found, before = [], [], ""
    for number, line in enumerate(code_only(text).split("\n"), start=1):
        for column, char in enumerate(line):
            if char == "{":
                context = (before + " " + line[:column]).split(";")[-1].split("}")[-1]
                inside = any(kind == "function" for kind, _, _ in scopes)
                is_function = (not inside and PARAMETER_LIST_END.search(context.strip())
                               and not CONTROL.search(context))
                names = re.findall(r"([\w:~]+)\s*\(", context)
                scopes.append(("function" if is_function else "block", number,
                               names[0] if names else "?"))
            elif char == "}" and scopes:
                kind, start, name = scopes.pop()
                if kind == "function":
                    found.append((name, start, number - start + 1))
        before = (before + " " + line)[-600:]
    return found


def long_functions():
    out = []
    for top in ("framework", "variants"):
        for path in sorted(glob.glob(os.path.join(SOURCE, top, "**", "*.cpp"), recursive=True)):
            relative = os.path.relpath(path, SOURCE)
            for name, start, lines in functions(read(relative)):
                if lines > MAX_FUNCTION_LINES:
                    out.append(f"{relative}:{start}: {name} has {lines} lines (at most {MAX_FUNCTION_LINES})")
    return out


def include_cycles():
    depends = {}
    for path in glob.glob(os.path.join(SOURCE, "framework", "**", "*.[ch]*"), recursive=True):
        if not path.endswith((".h", ".cpp")):
            continue
        relative = os.path.relpath(path, SOURCE)
        unit = os.path.splitext(relative)[0]
        for included in re.findall(r'^#include "(framework/[^"]+)\.h"', read(relative), re.M):
            if included != unit:
                depends.setdefault(unit, set()).add(included)
    # Tarjan's strongly connected components.
    index, low, stack, on_stack, cycles = {}, {}, [], set(), []

    def visit(unit):
        index[unit] = low[unit] = len(index)
        stack.append(unit)
        on_stack.add(unit)
        for other in depends.get(unit, ()):
            if other not in index:
                visit(other)
                low[unit] = min(low[unit], low[other])
            elif other in on_stack:
                low[unit] = min(low[unit], index[other])
        if low[unit] == index[unit]:
            component = set()
            while True:
                other = stack.pop()
                on_stack.discard(other)
                component.add(other)
                if other == unit:
                    break
            if len(component) > 1 and component not in ALLOWED_CYCLES:
                cycles.append(sorted(component))

    sys.setrecursionlimit(10000)
    for unit in sorted(depends):
        if unit not in index:
            visit(unit)
    return cycles


def slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


@functools.lru_cache(maxsize=None)
def anchors(page):
    """A page's sections: its headings' anchors and its explicit <a id="..."> ones."""
    text = read(page)
    return ({slug(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", text, re.M)} |
            set(re.findall(r'<a id="([\w-]+)"', text)))


REPOSITORY_PATH = re.compile(
    r"(?<![\w/.-])((?:framework|variants|shaders|tests|experiments|analysis|scripts|docs)/[\w./-]*[\w/])")
SECTION_LINK = re.compile(r"(docs/[\w/-]+\.md)#([\w-]+)")
RELATIVE_LINK = re.compile(r"\]\(([\w./-]+\.md)(?:#([\w-]+))?\)")


def broken_references():
    out = []
    pages = ["README.md"] + sorted(os.path.relpath(p, SOURCE) for p in
                                   glob.glob(os.path.join(SOURCE, "docs", "**", "*.md"), recursive=True))
    for page in pages:
        text = read(page)
        for match in REPOSITORY_PATH.finditer(text):
            path = match.group(1)
            if text[max(0, match.start() - 2):match.start()] == "](":
                continue  # a link, relative to the page: checked below
            following = text[match.end():match.end() + 2]
            if any(c in following for c in "<{*"):
                continue  # a pattern: experiments/ablation_<X>.toml, keyframe_track.{h,cpp}
            if not os.path.exists(os.path.join(SOURCE, path)):
                out.append(f"{page}: names {path}, which does not exist")
        for anchor in re.findall(r"\]\(#([\w-]+)\)", text):
            if anchor not in anchors(page):
                out.append(f"{page}: links to #{anchor}: no such section on the page")
        for match in RELATIVE_LINK.finditer(text):
            target = os.path.normpath(os.path.join(os.path.dirname(page), match.group(1)))
            if not os.path.exists(os.path.join(SOURCE, target)):
                out.append(f"{page}: links to {match.group(1)}, which does not exist")
            elif match.group(2) and match.group(2) not in anchors(target):
                out.append(f"{page}: links to {match.group(1)}#{match.group(2)}: no such section")
    code = []
    for top in ("framework", "variants", "shaders", "tests", "scripts", "analysis", "experiments", "docs"):
        code += glob.glob(os.path.join(SOURCE, top, "**", "*"), recursive=True)
    for path in [os.path.join(SOURCE, "README.md")] + code:
        if not os.path.isfile(path) or path.endswith((".exr", ".png", ".glb", ".bin", ".obj", ".pyc")):
            continue
        relative = os.path.relpath(path, SOURCE)
        try:
            text = read(relative)
        except UnicodeDecodeError:
            continue
        for page, anchor in SECTION_LINK.findall(text):
            if not os.path.exists(os.path.join(SOURCE, page)):
                out.append(f"{relative}: names {page}#{anchor}: no such page")
            elif anchor not in anchors(page):
                out.append(f"{relative}: names {page}#{anchor}: no such section")
    return out


def undocumented_variants(lpvlab):
    listing = json.loads(subprocess.run([lpvlab, "list", "--json"], check=True, capture_output=True,
                                        text=True).stdout)
    names = sorted({entry["name"] for entry in listing["strategies"] + listing["methods"]})
    return [f"{name}: no docs/variants/{name}.md" for name in names
            if not os.path.exists(os.path.join(SOURCE, "docs", "variants", name + ".md"))]


def conventions():
    out = []
    version = re.search(r"project\(lpvlab VERSION ([\d.]+)", read("CMakeLists.txt")).group(1)
    if not os.path.isfile(os.path.join(SOURCE, "LICENSE")):
        out.append("no LICENSE")
    if not os.path.isfile(os.path.join(SOURCE, "CITATION.cff")):
        out.append("no CITATION.cff")
    else:
        citation = read("CITATION.cff")
        for key in ("cff-version", "message", "title", "authors", "version", "license"):
            if not re.search(rf"^{key}:", citation, re.M):
                out.append(f"CITATION.cff: no {key}")
        cited = re.search(r'^version:\s*"?([\w.]+)"?', citation, re.M)
        if cited and cited.group(1) != version:
            out.append(f"CITATION.cff: version {cited.group(1)}, but CMakeLists.txt builds {version}")
    if not os.path.isfile(os.path.join(SOURCE, "CHANGELOG.md")):
        out.append("no CHANGELOG.md")
    elif not re.search(rf"^## (Unreleased|{re.escape(version)})\b", read("CHANGELOG.md"), re.M):
        out.append(f"CHANGELOG.md: no section for {version} or Unreleased")
    return out


def main():
    failures = [("functions over %d lines" % MAX_FUNCTION_LINES, long_functions()),
                ("include cycles among framework's units", [" <-> ".join(c) for c in include_cycles()]),
                ("documentation naming what does not exist", broken_references()),
                ("missing conventions (licence, citation, changelog)", conventions())]
    if len(sys.argv) > 1:
        failures.append(("strategies or methods without their page", undocumented_variants(sys.argv[1])))
    failed = False
    for title, problems in failures:
        if problems:
            failed = True
            print(f"FAIL: {title}:")
            for problem in problems:
                print("  " + problem)
        else:
            print(f"ok: no {title}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
