#!/usr/bin/env python3
"""The structure rules of docs/ARCHITECTURE.md, checked on the source tree.

Usage: scripts/check_structure.py [ROOT]     (exit 0: every rule holds; exit 1: each breach printed as file:line)

Rules:
  layers     a file of layer L (include/ompl_glider/L/ or src/L/) includes only headers of L, of the layers below
             L in LAYERS, and the top-level headers (ompl_glider/*.h); so no include runs up a layer and no two
             folders include each other. apps/ may include every layer.
  planner-free mission
             no file of src/mission/ or include/ompl_glider/mission/ includes a header of planners/,
             reachability/ or stints/ (relative includes too), though they lie below it: the pipeline asks for a
             planner by name or by family through the registry (registry/PlannerRegistry.h) and speaks to it
             through ompl/PipelinePlanner.h only.
  size       no file in src/, apps/ or python/src over MAX_FILE_LINES lines.
  functions  no function there over MAX_FUNCTION_LINES lines (from its opening to its closing brace).
  no-issues  no "issue N" in the code or the installed headers: the code says what it does and cites the literature.
  citations  sources cite by the keys of docs/REFERENCES.md ("[EichhornRAS] Eq. 5"), not by author and year.
  no-flags   no command-line flag ("--grid-size") in a string of the library (src/, include/): the library names
             settings by their mission fields, and each front end words them (MissionSpec::term(), SettingWords).
  outcomes   no code searches the words of an outcome (a no-path reason, a switch reason, a re-flight note) or
             compares them to a text: it branches on the typed cause (ompl/NoPath.h's NoPathCause); nor does the
             mission layer or a front end search an error's message to place it: Error::field() says the setting.
"""
import os
import re
import sys

# Top to bottom: a layer may include the layers after it.
LAYERS = ["mpi", "output", "mission", "registry", "reachability", "stints", "planners", "routes", "reference",
          "execution", "ompl", "cost", "environment", "current", "io", "core"]
MAX_FILE_LINES = 600
# the mission layer names no planner: the layers whose headers it may not include, though they lie below it
MISSION = ["src/mission", "include/ompl_glider/mission"]
PLANNER_LAYERS = ["planners", "reachability", "stints"]
SIZED = ["src", "apps", "python/src"]  # the size rules cover the library and both front ends
ISSUE_WORD = re.compile(r"\bissues? #?\d+", re.I)
MAX_FUNCTION_LINES = 150
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]ompl_glider/([^/">]+)/')
RELATIVE_INCLUDE = re.compile(r'^\s*#\s*include\s*"((?:\.\./)+[^"]+)"')
# an author-year citation: "Akima (1970)", "Brent 1973", "Lolla et al. 2014"
# a search in, a cut of, or a comparison with the words of an outcome
OUTCOME_TEXT = re.compile(r"\b(?:reason|why_?|switchReason|reflightNote|noPath\.what)\w*\s*(?:\(\))?\s*(?:\.|->)\s*"
                          r"(?:r?find|find_first_of|find_last_of|substr|compare|starts_with|ends_with)\s*\(|"
                          r"\b(?:reason|switchReason|reflightNote)\s*[!=]=\s*\"")
# a flag inside a string literal of code
FLAG_IN_STRING = re.compile(r'"(?:[^"\\\n]|\\.)*?(?<![\w-])(--[a-z][a-z0-9-]*)')
# a search in an error's message
ERROR_TEXT = re.compile(r"\bwhat\w*\s*(?:\(\))?\s*(?:\.|->)\s*(?:r?find|find_first_of|substr|compare|starts_with)\s*\(|"
                        r"\.what\(\)\)\.(?:r?find|substr|compare)\s*\(")
ERROR_FOLDERS = ["src/mission", "src/registry", "apps", "python/src"]
OUTCOME_FOLDERS = ["src/mission", "src/planners", "src/reachability", "src/ompl", "src/routes", "src/stints",
                   "src/execution", "src/output"]
AUTHOR_YEAR = re.compile(r"\b[A-Z][a-z]+(?: et al\.)?,? \(?(19|20)\d\d\)?")


def layer_of(rel):
    m = re.match(r"(?:include/ompl_glider|src)/([^/]+)/", rel)
    return m.group(1) if m else None


def source_files(root, folders, exts=(".h", ".cpp")):
    for folder in folders:
        for dirpath, _, names in os.walk(os.path.join(root, folder)):
            for name in sorted(names):
                if name.endswith(exts):
                    path = os.path.join(dirpath, name)
                    yield path, os.path.relpath(path, root)


def included_layers(root, path):
    """(line number, layer) of each include of @p path that names a layer's header: "ompl_glider/L/..." or a
    relative include that resolves into include/ompl_glider/L/ or src/L/ (top-level headers left out)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            target = m.group(1) if m else None
            r = RELATIVE_INCLUDE.match(line)
            if r:  # a relative include into another folder of src/
                resolved = os.path.relpath(os.path.normpath(os.path.join(os.path.dirname(path), r.group(1))), root)
                target = layer_of(resolved)
            if target and not target.endswith(".h"):  # not a top-level header
                yield number, target


def check_layers(root):
    breaches = []
    for path, rel in source_files(root, ["include/ompl_glider", "src"]):
        own = layer_of(rel)
        if own is None:
            continue
        if own not in LAYERS:
            breaches.append(f"{rel}: layer '{own}' is not in the list of layers (scripts/check_structure.py)")
            continue
        allowed = set(LAYERS[LAYERS.index(own):])
        for number, target in included_layers(root, path):
            if target not in allowed:
                breaches.append(f"{rel}:{number}: layer '{own}' includes layer '{target}' above it")
    return breaches


def check_planner_free_mission(root):
    breaches = []
    for path, rel in source_files(root, MISSION):
        for number, target in included_layers(root, path):
            if target in PLANNER_LAYERS:
                breaches.append(f"{rel}:{number}: mission/ includes a header of {target}/: ask the registry for the "
                                "planner (by name or family) and speak to it through ompl/PipelinePlanner.h")
    return breaches


def strip_comments_and_strings(text):
    """The text with comments and string/character literals blanked (newlines kept, so lines still count)."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text[i] == "R" and re.match(r'R"([^(\s]*)\(', text[i:i + 20]):
            delim = ")" + re.match(r'R"([^(\s]*)\(', text[i:i + 20]).group(1) + '"'
            j = text.find(delim, i)
            j = n if j < 0 else j + len(delim)
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif text[i] in "\"'" and not (text[i] == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 separators
            quote, j = text[i], i + 1
            while j < n and text[j] != quote and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(quote * 2)
            i = j + 1
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


FUNCTION_HEAD = re.compile(r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->[^{]*)?$")
CONSTRUCTOR_HEAD = re.compile(r"\)\s*:[^;]*$", re.S)
SCOPE_HEAD = re.compile(r"\b(namespace|class|struct|union|enum)\b[^()]*$")


def functions(path):
    """(first line, lines, name) of every function defined at namespace or class scope (lambdas count with their
    enclosing function)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = strip_comments_and_strings(f.read())
    stack, found, last = [], [], 0
    for i, c in enumerate(text):
        if c == "{":
            head = text[last:i].strip()
            kind = "block"
            if SCOPE_HEAD.search(head) or head.endswith('extern ""'):
                kind = "scope"
            elif FUNCTION_HEAD.search(head) or CONSTRUCTOR_HEAD.search(head):
                bare = re.sub(r"\([^()]*\)", "", head)
                if all(k == "scope" for k, _, _ in stack) and not bare.rstrip().endswith("]"):
                    kind = "function"
            names = re.findall(r"([~\w:]+)\s*\(", head)
            stack.append((kind, text.count("\n", 0, i) + 1, names[0] if names else "?"))
            last = i + 1
        elif c == "}":
            if stack:
                kind, first, name = stack.pop()
                if kind == "function":
                    found.append((first, text.count("\n", 0, i) + 1 - first + 1, name))
            last = i + 1
        elif c == ";":
            last = i + 1
    return found


def check_sizes(root):
    breaches = []
    for path, rel in source_files(root, SIZED):
        with open(path, encoding="utf-8", errors="replace") as f:
            count = sum(1 for _ in f)
        if count > MAX_FILE_LINES:
            breaches.append(f"{rel}: {count} lines (at most {MAX_FILE_LINES})")
        for first, length, name in functions(path):
            if length > MAX_FUNCTION_LINES:
                breaches.append(f"{rel}:{first}: function {name} has {length} lines (at most {MAX_FUNCTION_LINES})")
    return breaches


def check_citations(root):
    breaches = []
    for path, rel in source_files(root, ["include/ompl_glider", "src"]):
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                comment = line.split("//", 1)[1] if "//" in line else ""
                m = AUTHOR_YEAR.search(comment)
                if m:
                    breaches.append(f"{rel}:{number}: cites '{m.group(0)}': cite by the key of docs/REFERENCES.md")
    return breaches


def check_no_issue_numbers(root):
    breaches = []
    for path, rel in source_files(root, ["include/ompl_glider"] + SIZED, (".h", ".cpp", ".py", ".pyi")):
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = ISSUE_WORD.search(line)
                if m:
                    breaches.append(f"{rel}:{number}: '{m.group(0)}': say what the code does, not which issue asked")
    return breaches


def code_lines(root, folders):
    """(rel, line number, line) of the code in @p folders, // comments left out (strings kept: a comparison with a
    string literal is what the rules look for)."""
    for path, rel in source_files(root, folders):
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                yield rel, number, line.split("//", 1)[0]


def pattern_breaches(root, folders, pattern, why):
    """Each line of @p folders that @p pattern matches, with why(match)."""
    return [f"{rel}:{number}: {why(m)}" for rel, number, line in code_lines(root, folders)
            for m in [pattern.search(line)] if m]


def check_outcomes(root):
    return (pattern_breaches(root, OUTCOME_FOLDERS, OUTCOME_TEXT,
                             lambda m: f"'{m.group(0)}' reads an outcome's words: branch on its cause") +
            pattern_breaches(root, ERROR_FOLDERS, ERROR_TEXT,
                             lambda m: f"'{m.group(0)}' reads an error's message: use Error::field()"))


def check_no_flags(root):
    return pattern_breaches(root, ["src", "include/ompl_glider"], FLAG_IN_STRING,
                            lambda m: f"'{m.group(1)}': name the setting (MissionSpec::term()), not a flag")


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    failed = False
    for rule, check in (("layers", check_layers), ("planner-free mission", check_planner_free_mission),
                        ("size", check_sizes), ("citations", check_citations),
                        ("no-issues", check_no_issue_numbers), ("outcomes", check_outcomes),
                        ("no-flags", check_no_flags)):
        breaches = check(root)
        print(f"{rule}: {'ok' if not breaches else str(len(breaches)) + ' breach(es)'}")
        for b in breaches:
            print("  " + b)
        failed = failed or bool(breaches)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
