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
  functions  no function there over MAX_FUNCTION_LINES lines (from its opening to its closing brace). The two limits
             are these constants only: the docs and the self-test read them from here.
  no-issues  no "issue N" in the code or the installed headers: the code says what it does and cites the literature.
  citations  sources cite by the keys of docs/REFERENCES.md ("[EichhornRAS] Eq. 5"), not by author and year.
  no-flags   no command-line flag ("--grid-size") in a string of the library (src/, include/): the library names
             settings by their mission fields, and each front end words them (MissionSpec::term(), SettingWords).
  outcomes   no code searches the words of an outcome (a no-path reason, a switch reason, a re-flight note) or
             compares them to a text: it branches on the typed cause (ompl/NoPath.h's NoPathCause); nor does the
             mission layer or a front end search an error's message to place it: Error::field() says the setting.
  inputs-problem
             no file of src/mission/problem/ (PROBLEM) or src/mission/inputs/ (INPUTS) includes a header of the other
             of the two or of src/mission/planning/ (PLANNING): a quoted include resolved as the compiler does
             ("../planning/PlanningInternal.h", "../inputs/X.h", any path that lands there). The installed headers
             (include/ompl_glider/mission/) are one folder for all of mission/ and are left to the layers rule.
  folders    the folders the rules name (the constants MISSION_SRC, PROBLEM, INPUTS, PLANNING, SETTINGS, ...) exist
             in the real tree (one that has src/mission/sources.cmake): renaming a folder is one line here. No rule
             takes a folder for tests by its name (settings/ is the mission's settings, not a test folder).
  paths      every file or folder that a comment (C++ // and /* */, # of Python, shell and CMake, a Python
             docstring) in src/, include/, apps/, python/src, tests/ or scripts/, or a doc (README.md, docs/*.md,
             examples/*.md, read whole) names exists in the tree (build folders and .git left out). A name is
             - a path from the top: src/..., include/..., apps/, python/, tests/, scripts/, docs/, examples/,
               benchmarks/, demos/, fuzz/, cmake/ (a folder with its slash or without; a glob such as
               examples/*.yaml must match something; without an extension, a program built from a source of that
               name: fuzz/fuzz_cli);
             - a path from a folder of src/ or include/ompl_glider/ (io/RemoteSource.h, ompl/PipelinePlanner.h,
               mission/planning/, gridded/ForecastFiles.cpp): it ends with an extension or a slash and some path of
               the tree ends with it; OMPL's own headers (ompl/base/..., ompl/geometric/...) are not ours;
             - a bare file name ending .cpp, .h, .py or .sh: some file of the tree has that name (or that name plus
               .in: a header CMake makes, Config.h); a lower-case .h is a C library's (netcdf.h) and not checked.
             Skipped: URLs; paths under build/ (not a name from the top); placeholders of usage texts and recipes:
             a path holding <...>, {...}, $, "...", or a part named by a metavariable (a single capital letter, NN,
             FILE, DIR, NAME, MISSION, TARGET, BEFORE, AFTER, ROOT, PATH, OUT, SRC, LAYER) or by an example's name
             (Foo, Bar, Baz, My..., my_...). Files made at run time (summary.json, route.csv) are no source names.
  literal-comparisons
             at most MAX_LITERAL_COMPARISONS lines of src/, apps/ and python/src (.h, .cpp; // comments dropped)
             compare with a string literal (== "...", != "...", "..." ==, "..." !=); over it, the count and the files
             with the most. The same count: LITERAL_COMMAND (docs/ARCHITECTURE.md).
"""
import os
import re
import sys

# Top to bottom: a layer may include the layers after it.
LAYERS = ["mpi", "output", "mission", "registry", "reachability", "stints", "planners", "routes", "reference",
          "execution", "ompl", "cost", "environment", "current", "io", "core"]
MAX_FILE_LINES = 600
# The folders the rules name, each once: a folder renamed is one line here (and the docs that name it).
MISSION_SRC = "src/mission"
MISSION_INCLUDE = "include/ompl_glider/mission"
PROBLEM = MISSION_SRC + "/problem"      # MissionProblem as a value
INPUTS = MISSION_SRC + "/inputs"        # what the problem reads
PLANNING = MISSION_SRC + "/planning"    # the pipeline
SETTINGS = MISSION_SRC + "/settings"    # what the front ends give
# the mission layer names no planner: the layers whose headers it may not include, though they lie below it
MISSION = [MISSION_SRC, MISSION_INCLUDE]
PLANNER_LAYERS = ["planners", "reachability", "stints"]
SIZED = ["src", "apps", "python/src"]  # the size rules cover the library and both front ends
ISSUE_WORD = re.compile(r"\bissues? #?\d+", re.I)
MAX_FUNCTION_LINES = 120
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
ERROR_FOLDERS = [MISSION_SRC, "src/registry", "apps", "python/src"]
OUTCOME_FOLDERS = [MISSION_SRC, "src/planners", "src/reachability", "src/ompl", "src/routes", "src/stints",
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


QUOTED_INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def included_files(root, path):
    """(line number, included path relative to @p root) of each quoted include of @p path that is not an installed
    header ("ompl_glider/..."): resolved as the compiler does, against the file's folder first, then against src/
    (the tests' include path); a file that exists in neither place is taken as against the file's folder."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            m = QUOTED_INCLUDE.match(line)
            if not m or m.group(1).startswith("ompl_glider/"):
                continue
            here = os.path.normpath(os.path.join(os.path.dirname(path), m.group(1)))
            in_src = os.path.normpath(os.path.join(root, "src", m.group(1)))
            target = here if os.path.exists(here) or not os.path.exists(in_src) else in_src
            yield number, os.path.relpath(target, root).replace(os.sep, "/")


def within(rel, folder):
    return rel == folder or rel.startswith(folder + "/")


# problem/ and inputs/ lie beside each other under the pipeline: neither includes the other's headers nor planning/'s
SEPARATE_MISSION_FOLDERS = {PROBLEM: [INPUTS, PLANNING], INPUTS: [PROBLEM, PLANNING]}


def check_inputs_problem(root):
    breaches = []
    for folder, forbidden in SEPARATE_MISSION_FOLDERS.items():
        for path, rel in source_files(root, [folder]):
            for number, target in included_files(root, path):
                for other in forbidden:
                    if within(target, other):
                        breaches.append(f"{rel}:{number}: {folder}/ includes {target} of {other}/")
    return breaches


def check_folders(root):
    """The folders the rules name exist (in a tree that lists the mission layer's sources): a renamed folder is
    renamed here too."""
    if not os.path.isfile(os.path.join(root, MISSION_SRC, "sources.cmake")):
        return []
    return [f"{folder}/: named by scripts/check_structure.py, no such folder"
            for folder in [MISSION_SRC, MISSION_INCLUDE, PROBLEM, INPUTS, PLANNING, SETTINGS] + SIZED
            if not os.path.isdir(os.path.join(root, folder))]


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


# a comparison with a string literal: settings, kinds and outcomes are typed once where they are read
LITERAL_COMPARISON = re.compile(r'(==|!=)[ \t]*"|"[ \t]*(==|!=)')
MAX_LITERAL_COMPARISONS = 99
LITERAL_COMMAND = ("find src apps python/src -name '*.h' -o -name '*.cpp' | sort | xargs sed 's://.*::' | "
                   "grep -cE '(==|!=)[[:blank:]]*\"|\"[[:blank:]]*(==|!=)'")


def check_literal_comparisons(root):
    per_file = {}
    for rel, _, line in code_lines(root, SIZED):
        if LITERAL_COMPARISON.search(line):
            per_file[rel] = per_file.get(rel, 0) + 1
    total = sum(per_file.values())
    if total <= MAX_LITERAL_COMPARISONS:
        return []
    top = sorted(per_file.items(), key=lambda kv: (-kv[1], kv[0]))[:10]
    return [f"{total} lines compare with a string literal (at most {MAX_LITERAL_COMPARISONS}; the count: "
            f"{LITERAL_COMMAND}); compare typed values (an enum, the registry's entry), not texts; the most:" +
            "".join(f"\n    {rel}: {count}" for rel, count in top)]


# The paths rule: every file or folder a comment or a doc names exists.
COMMENTED = ["src", "include", "apps", "python/src", "tests", "scripts"]  # whose comments are read
DOCS = ["README.md", "docs/*.md", "examples/*.md"]                       # read whole
BUILD_DIRS = re.compile(r"^(build|build-[^/]*|\.git|_build)$")            # the tree outside these
TOP_FOLDERS = ["src", "include", "apps", "python", "tests", "scripts", "docs", "examples", "benchmarks", "demos",
               "fuzz", "cmake"]
SOURCE_EXT = ("cpp", "h", "py", "sh")
# a path from the top of the tree: src/mission/planning/Isochrones.cpp, docs/MPI.md, examples/*.yaml, tests/badinput/
ROOTED_PATH = re.compile(r"(?<![\w./$@-])((?:" + "|".join(TOP_FOLDERS) + r")/[\w./*<>{}$-]*)")
# a path from a layer's folder (io/RemoteSource.h, mission/planning/, gridded/ForecastFiles.cpp): its first folder is
# a folder of src/ or include/ompl_glider/ (found in the tree), and it ends with a file's extension or a slash
LAYER_PATH = re.compile(r"(?<![\w./$@-])([a-z_]+/[\w./*<>{}$-]*)")
BARE_NAME = re.compile(r"(?<![\w./$@<*-])([A-Za-z_][\w-]*\.(?:" + "|".join(SOURCE_EXT) + r"))(?![\w/*-]|\.\w)")
URL = re.compile(r"\b[a-z][a-z0-9+.-]*://\S*")
# OMPL's own headers share the name of the ompl/ layer
EXTERNAL = re.compile(r"^ompl/(base|geometric|control|tools|util|datastructures|multilevel|config\.h)\b")
# metavariables of usage texts (FILE.yaml, BEFORE/apps/glider_plan) and names of examples (MyFlow.h, Foo.cpp)
PLACEHOLDER = re.compile(r"^([A-Z]|NN|FILE|FILES|DIR|NAME|MISSION|TARGET|BEFORE|AFTER|ROOT|PATH|OUT|SRC|SOURCE_DIR|"
                         r"LAYER|Foo|Bar|Baz|My[A-Z_]\w*|my_\w+)$")
# a header in lower case (netcdf.h, dbdfrmat.h) is a C library's: the project's headers are named in CamelCase
C_HEADER = re.compile(r"^[a-z0-9_]+\.h$")


def tree_paths(root):
    """Every file and folder of the tree outside the build folders, relative to @p root."""
    found = set()
    for dirpath, dirs, names in os.walk(root):
        dirs[:] = [d for d in dirs if not BUILD_DIRS.match(d)]
        rel = os.path.relpath(dirpath, root).replace(os.sep, "/")
        for name in dirs + names:
            found.add(name if rel == "." else rel + "/" + name)
    return found


def comments(path):
    """(line number, text) of the comments of a source file: // and /* */ in C++, # in Python, shell and CMake
    (a Python docstring too)."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    if path.endswith((".h", ".cpp", ".hpp", ".cc")):
        for m in re.finditer(r'//[^\n]*|/\*.*?\*/|"(?:[^"\\\n]|\\.)*"', text, re.S):
            if not m.group(0).startswith('"'):
                first = text.count("\n", 0, m.start()) + 1
                for k, line in enumerate(m.group(0).split("\n")):
                    yield first + k, line
    else:
        for m in re.finditer(r'"""(.*?)"""|(?<![\w"\'$])#(?![!{])[^\n]*|"(?:[^"\\\n]|\\.)*"|\'(?:[^\'\\\n]|\\.)*\'',
                             text, re.S):
            g = m.group(0)
            if g.startswith('"""') or g.startswith("#"):
                first = text.count("\n", 0, m.start()) + 1
                for k, line in enumerate(g.split("\n")):
                    yield first + k, line


def named_paths(line, folders):
    """(kind, path) of each path @p line names: 'rooted', 'layer' (first folder among @p folders) or 'bare'."""
    line = URL.sub(" ", line)
    for m in ROOTED_PATH.finditer(line):
        yield "rooted", m.group(1)
    for m in LAYER_PATH.finditer(line):
        path = m.group(1).rstrip(".,:;")
        if path.split("/")[0] in folders and path.split("/")[0] not in TOP_FOLDERS and \
                (path.endswith("/") or re.search(r"\.\w+$", path)):
            yield "layer", path
    for m in BARE_NAME.finditer(line):
        yield "bare", m.group(1)


def placeholder(path):
    return (re.search(r"[<>{}$]|\.\.\.|…", path) is not None or
            any(PLACEHOLDER.match(part.split(".")[0]) for part in path.split("/")))


def path_exists(kind, path, paths, names):
    path = path.rstrip(".,:;").rstrip("/")
    if kind == "bare":  # anywhere in the tree, or a header made from a template (Config.h.in)
        return path in names or path + ".in" in names or C_HEADER.match(path) is not None
    if kind == "layer" and EXTERNAL.match(path):
        return True
    pattern = re.compile(("" if kind == "rooted" else r"(^|.*/)") +
                         re.escape(path).replace(r"\*\*", ".*").replace(r"\*", "[^/]*") + "$")
    if any(pattern.match(p) for p in paths):
        return True
    # a file named without its extension: a program built from it (fuzz/fuzz_cli)
    stem = re.compile(pattern.pattern[:-1] + r"\.(?:" + "|".join(SOURCE_EXT) + ")$")
    return not re.search(r"\.\w+$", path) and any(stem.match(p) for p in paths)


def check_paths(root):
    paths = tree_paths(root)
    names = {p.rsplit("/", 1)[-1] for p in paths}
    folders = {p.rsplit("/", 1)[-1] for p in paths if re.match(r"(src|include/ompl_glider)/", p) and
               os.path.isdir(os.path.join(root, p))}
    texts = []  # (rel, numbered lines)
    for pattern in DOCS:
        for rel in sorted(p for p in paths if re.fullmatch(re.escape(pattern).replace(r"\*", "[^/]*"), p)):
            with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
                texts.append((rel, list(enumerate(f.read().split("\n"), 1))))
    for rel in sorted(p for p in paths if p.split("/")[0] in {c.split("/")[0] for c in COMMENTED} and
                      any(within(p, c) for c in COMMENTED) and
                      (p.endswith((".h", ".cpp", ".py", ".sh", ".cmake")) or p.endswith("CMakeLists.txt"))):
        texts.append((rel, list(comments(os.path.join(root, rel)))))
    breaches = []
    for rel, lines in texts:
        for number, line in lines:
            for kind, path in named_paths(line, folders):
                if not placeholder(path) and not path_exists(kind, path, paths, names):
                    breaches.append(f"{rel}:{number}: names {path.rstrip('.,:;')}, which does not exist")
    return breaches


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    failed = False
    for rule, check in (("layers", check_layers), ("planner-free mission", check_planner_free_mission),
                        ("size", check_sizes), ("citations", check_citations),
                        ("no-issues", check_no_issue_numbers), ("outcomes", check_outcomes),
                        ("no-flags", check_no_flags), ("inputs-problem", check_inputs_problem),
                        ("folders", check_folders), ("paths", check_paths),
                        ("literal-comparisons", check_literal_comparisons)):
        breaches = check(root)
        print(f"{rule}: {'ok' if not breaches else str(len(breaches)) + ' breach(es)'}")
        for b in breaches:
            print("  " + b)
        failed = failed or bool(breaches)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
