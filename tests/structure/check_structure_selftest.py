#!/usr/bin/env python3
"""The structure checker catches what it claims to: an upward include, a mission/ include of planners/,
reachability/ or stints/, a long file, a long function (in the library and in the front ends), an author-year
citation, an issue number, a search in an outcome's words or an error's message, a command-line flag in the library's
strings, an include between problem/, inputs/ and planning/ of mission/, a folder the rules name that is gone, a path
a comment or a doc names that does not exist, too many comparisons with a string literal; and passes a tree that
keeps the rules, and the real tree on the planner-free mission rule. The limits come from the checker's constants.
Run by ctest (structure.checker_selftest)."""
import importlib.util
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check_structure.py")
_spec = importlib.util.spec_from_file_location("check_structure", SCRIPT)
rules = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(rules)
FUNCTION_LIMIT, FILE_LIMIT = rules.MAX_FUNCTION_LINES, rules.MAX_FILE_LINES


def tree(files):
    root = tempfile.mkdtemp(prefix="structure-")
    for rel, text in files.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    return root


def run(root):
    p = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True)
    return p.returncode, p.stdout


def function(name, body_lines):
    return f"int {name}(int a)\n{{\n" + "    a += 1;\n" * body_lines + "    return a;\n}\n"


failures = []
checks = 0


def expect(condition, what, output):
    global checks
    checks += 1
    if not condition:
        failures.append(what + "\n" + output)


good = {
    "include/ompl_glider/current/Field.h": '#include "ompl_glider/Geometry.h"\n',
    "src/current/Field.cpp": '#include "ompl_glider/current/Field.h"\n#include "ompl_glider/io/Time.h"\n' +
                             function("f", FUNCTION_LIMIT - 10),
    "src/mission/Plan.cpp": '#include "ompl_glider/registry/X.h"\n#include "ompl_glider/current/Field.h"\n'
                            "// the search of [EichhornRAS] Eq. 5\n",
}
code, out = run(tree(good))
expect(code == 0, "a tree that keeps the rules must pass", out)

upward = dict(good)
upward["src/current/Bad.cpp"] = '#include "ompl_glider/mission/MissionSpec.h"\n'
code, out = run(tree(upward))
expect(code == 1 and "src/current/Bad.cpp:1: layer 'current' includes layer 'mission'" in out,
       "an upward include must fail with file:line", out)

relative = dict(good)
relative["src/current/netcdf/Rel.cpp"] = '#include "../../output/Writer.h"\n'
code, out = run(tree(relative))
expect(code == 1 and "src/current/netcdf/Rel.cpp:1: layer 'current' includes layer 'output'" in out,
       "a relative upward include must fail", out)

planner_named = dict(good)
planner_named["src/mission/Named.cpp"] = ('#include "ompl_glider/registry/PlannerRegistry.h"\n'
                                          '#include "ompl_glider/planners/ZAStarTVE.h"\n'
                                          '// #include "ompl_glider/planners/Wavefront.h" in a comment is no include\n')
planner_named["include/ompl_glider/mission/Level.h"] = '#include <ompl_glider/reachability/LevelSet.h>\n'
planner_named["src/mission/sub/Rel.cpp"] = '#include "../../reachability/LevelSetInternal.h"\n'
planner_named["src/mission/Stint.cpp"] = '#include "ompl_glider/stints/StintPlanner.h"\n'
planner_named["src/registry/Ok.cpp"] = '#include "ompl_glider/planners/ZAStarTVE.h"\n'  # the registry may
code, out = run(tree(planner_named))
expect(code == 1 and "src/mission/Named.cpp:2: mission/ includes a header of planners/" in out and
       "include/ompl_glider/mission/Level.h:1: mission/ includes a header of reachability/" in out and
       "src/mission/sub/Rel.cpp:1: mission/ includes a header of reachability/" in out and
       "src/mission/Stint.cpp:1: mission/ includes a header of stints/" in out and
       "Named.cpp:3" not in out and "Ok.cpp" not in out and "layers: ok" in out,
       "a mission/ include of planners/, reachability/ or stints/ (relative too) must fail, the registry's not", out)

real = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
code, out = run(real)
expect("planner-free mission: ok" in out,
       "the real tree's mission/ must include no header of planners/, reachability/ or stints/", out)

long_function = dict(good)
long_function["src/current/Long.cpp"] = function("tooLong", FUNCTION_LIMIT + 10)
code, out = run(tree(long_function))
expect(code == 1 and f"function tooLong has {FUNCTION_LIMIT + 13} lines" in out,
       f"a {FUNCTION_LIMIT + 13}-line function must fail", out)

BIG = FILE_LIMIT // 14 + 1  # functions of 14 lines: one file over the limit
long_file = dict(good)
long_file["src/current/Big.cpp"] = "".join(function(f"g{i}", 10) for i in range(BIG))
code, out = run(tree(long_file))
expect(code == 1 and f"src/current/Big.cpp: {14 * BIG} lines" in out, f"a {14 * BIG}-line file must fail", out)

citation = dict(good)
citation["src/current/Cite.cpp"] = "// the spline of Akima (1970)\n"
code, out = run(tree(citation))
expect(code == 1 and "Akima (1970)" in out, "an author-year citation must fail", out)

front_ends = dict(good)
front_ends["apps/tool/Flags.cpp"] = function("defineEverything", FUNCTION_LIMIT + 10)
front_ends["python/src/Big.cpp"] = "".join(function(f"h{i}", 10) for i in range(BIG))
code, out = run(tree(front_ends))
expect(code == 1 and f"apps/tool/Flags.cpp:2: function defineEverything has {FUNCTION_LIMIT + 13} lines" in out and
       f"python/src/Big.cpp: {14 * BIG} lines" in out, "the size rules must cover apps/ and python/src", out)

bookkeeping = dict(good)
bookkeeping["include/ompl_glider/current/Old.h"] = "/// @brief The jet of issue 12.\n"
code, out = run(tree(bookkeeping))
expect(code == 1 and "include/ompl_glider/current/Old.h:1: 'issue 12'" in out,
       "an issue number in an installed header must fail", out)

unknown = dict(good)
unknown["src/gadgets/G.cpp"] = "\n"
code, out = run(tree(unknown))
expect(code == 1 and "layer 'gadgets' is not in the list" in out, "a folder outside the layer list must fail", out)

outcome = dict(good)
outcome["src/mission/Switch.cpp"] = ('bool proven(const std::string &reason)\n{\n'
                                     '    return reason.find("never reaches") != std::string::npos;\n}\n'
                                     '// a comment may say r.reason.find("x")\n')
outcome["src/output/Note.cpp"] = 'bool same(const P &p)\n{\n    return p.switchReason == "lattice";\n}\n'
code, out = run(tree(outcome))
expect(code == 1 and "src/mission/Switch.cpp:3: 'reason.find('" in out and "Switch.cpp:5" not in out and
       "src/output/Note.cpp:3: 'switchReason == \"'" in out,
       "a search in or a comparison with an outcome's words must fail (a comment may mention one)", out)

error_text = dict(good)
error_text["apps/tool/Place.cpp"] = ('void place(const Error &e)\n{\n'
                                     '    if (std::string(e.what()).find("time_units") != std::string::npos) {}\n'
                                     '    const std::string what = e.what();\n'
                                     '    if (what.rfind("--", 0) == 0) {}\n}\n')
code, out = run(tree(error_text))
expect(code == 1 and "apps/tool/Place.cpp:3:" in out and "apps/tool/Place.cpp:5: 'what.rfind('" in out,
       "a search in an error's message must fail in the front ends", out)

flags = dict(good)
flags["src/mission/Advice.cpp"] = ('std::string advice()\n{\n    return "raise it (--time-limit)";\n}\n'
                                   '// the command line calls it --time-limit\n'
                                   'const char *range = "a--b";\n')
flags["include/ompl_glider/mission/Words.h"] = 'const char *w = "give \\"--depth\\" here";\n'
code, out = run(tree(flags))
expect(code == 1 and "src/mission/Advice.cpp:3: '--time-limit'" in out and "Advice.cpp:5" not in out and
       "Advice.cpp:6" not in out and "include/ompl_glider/mission/Words.h:1: '--depth'" in out,
       "a command-line flag in a string of the library must fail (not in a comment, not inside a word)", out)

settings = rules.SETTINGS  # the mission's settings (settings/): a folder of code, not of tests
separate = dict(good)
separate[rules.PROBLEM + "/Endpoints.cpp"] = ('#include "ProblemParts.h"\n'
                                              '#include "../planning/PlanningInternal.h"\n'
                                              '// #include "../inputs/Reader.h" in a comment is no include\n'
                                              '#include "../../mission/inputs/Reader.h"\n')
separate[rules.PROBLEM + "/ProblemParts.h"] = "\n"
separate[rules.INPUTS + "/Field.cpp"] = '#include "../problem/ProblemParts.h"\n#include "../../io/NumberText.h"\n'
separate[rules.PLANNING + "/Plan.cpp"] = '#include "../problem/ProblemParts.h"\n#include "../inputs/Reader.h"\n'
separate[settings + "/Ranges.cpp"] = '#include "../problem/ProblemParts.h"\n'
code, out = run(tree(separate))
expect(code == 1 and f"{rules.PROBLEM}/Endpoints.cpp:2: " in out and f"{rules.PROBLEM}/Endpoints.cpp:4: " in out and
       f"{rules.INPUTS}/Field.cpp:1: " in out and "Endpoints.cpp:1:" not in out and "Endpoints.cpp:3:" not in out and
       "Field.cpp:2:" not in out and "Plan.cpp" not in out and "Ranges.cpp" not in out,
       "problem/ and inputs/ must include neither each other's headers nor planning/'s (planning/ may)", out)

folders = dict(good)
folders[rules.MISSION_SRC + "/sources.cmake"] = "\n"
folders[rules.PROBLEM + "/A.cpp"] = "\n"
folders[rules.INPUTS + "/B.cpp"] = "\n"
folders[rules.PLANNING + "/C.cpp"] = "\n"
folders["include/ompl_glider/mission/D.h"] = "\n"
folders["apps/tool/main.cpp"] = "\n"
folders["python/src/Module.cpp"] = "\n"
code, out = run(tree(folders))
expect(code == 1 and f"{settings}/: named by scripts/check_structure.py, no such folder" in out and
       f"{rules.PROBLEM}/:" not in out, "a folder the rules name that the tree lacks must fail", out)
folders[settings + "/E.cpp"] = "\n"
code, out = run(tree(folders))
expect(code == 0, "the folders the rules name, all there, must pass", out)

named = dict(good)
named["docs/GUIDE.md"] = ("See `src/current/Field.cpp`, `io/Time.h`, `current/`, Field.cpp, `examples/*.yaml`, "
                          "docs/X.md, `src/<layer>/`, `include/ompl_glider/current/MyFlow.h`, build/apps/glider_plan, "
                          "https://example.org/src/Gone.cpp, `ompl/base/Planner.h`, netcdf.h, fuzz/fuzz_cli.\n"
                          "Gone: `docs/OLD.md`, and `examples/*.json`\n")
named["examples/a.yaml"] = "\n"
named["include/ompl_glider/io/Time.h"] = "\n"
named["fuzz/fuzz_cli.cpp"] = "\n"
named["README.md"] = "Read [the guide](docs/GUIDE.md); src/current/Gone.cpp.\n"
named["src/current/Named.cpp"] = ('// as in io/Time.h and Field.cpp\n'
                                  'const char *s = "src/current/NotAComment.cpp";\n'
                                  '/* a block:\n   io/Gone.h */\n'
                                  'int x; // Missing.cpp\n')
named[settings + "/Words.cpp"] = "// see src/mission/Gone.cpp\n"
named["tests/current/check.py"] = '"""Checks tests/current/gone.sh."""\nx = "#tests/nope.sh"  # scripts/run.sh\n'
named["scripts/run.sh"] = "# writes build/out.csv\n"
code, out = run(tree(named))
expect(code == 1 and "docs/GUIDE.md:2: names docs/OLD.md" in out and "docs/GUIDE.md:2: names examples/*.json" in out and
       "README.md:1: names src/current/Gone.cpp" in out and "src/current/Named.cpp:4: names io/Gone.h" in out and
       "src/current/Named.cpp:5: names Missing.cpp" in out and f"{settings}/Words.cpp:1: names src/mission/Gone.cpp" in
       out and "tests/current/check.py:1: names tests/current/gone.sh" in out and "GUIDE.md:1" not in out and
       "NotAComment" not in out and "Named.cpp:1" not in out and "nope.sh" not in out and "scripts/run.sh" not in out
       and "paths: 7 breach(es)" in out,
       "a path a doc or a comment names that does not exist must fail (not a URL, a placeholder, a string, build/)",
       out)

literals = dict(good)
limit = rules.MAX_LITERAL_COMPARISONS
literals[settings + "/Kinds.cpp"] = ('bool k(const std::string &s)\n{\n' +
                                     '    if (s == "a" || "b" != s) return true;\n' * (limit - 1) +
                                     '    // if (s == "c") in a comment\n    return s != "d";\n}\n')
code, out = run(tree(literals))
expect(code == 0, f"{limit} lines comparing with a string literal must pass", out)
literals["apps/tool/Mode.cpp"] = 'bool m(const char *s) { return std::string(s) == "x" && s[0] != \'"\'; }\n'
code, out = run(tree(literals))
expect(code == 1 and f"{limit + 1} lines compare with a string literal" in out and
       f"{settings}/Kinds.cpp: {limit}" in out and "apps/tool/Mode.cpp: 1" in out,
       f"{limit + 1} lines comparing with a string literal must fail, naming the files (settings/ counts too)", out)

for f in failures:
    print("FAILED: " + f)
print(f"{checks - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
