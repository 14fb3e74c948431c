#!/usr/bin/env python3
"""The structure checker catches what it claims to: an upward include, a mission/ include of planners/,
reachability/ or stints/, a long file, a long function (in the library and in the front ends), an author-year
citation, an issue number, a search in an outcome's words or an error's message, a command-line flag in the library's
strings; and passes a tree that keeps the rules, and the real tree on the planner-free mission rule. Run by ctest
(structure.checker_selftest)."""
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check_structure.py")


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
                             function("f", 140),
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
long_function["src/current/Long.cpp"] = function("tooLong", 160)
code, out = run(tree(long_function))
expect(code == 1 and "function tooLong has 163 lines" in out, "a 163-line function must fail", out)

long_file = dict(good)
long_file["src/current/Big.cpp"] = "".join(function(f"g{i}", 10) for i in range(60))
code, out = run(tree(long_file))
expect(code == 1 and "src/current/Big.cpp: 840 lines" in out, "an 840-line file must fail", out)

citation = dict(good)
citation["src/current/Cite.cpp"] = "// the spline of Akima (1970)\n"
code, out = run(tree(citation))
expect(code == 1 and "Akima (1970)" in out, "an author-year citation must fail", out)

front_ends = dict(good)
front_ends["apps/tool/Flags.cpp"] = function("defineEverything", 160)
front_ends["python/src/Big.cpp"] = "".join(function(f"h{i}", 10) for i in range(60))
code, out = run(tree(front_ends))
expect(code == 1 and "apps/tool/Flags.cpp:2: function defineEverything has 163 lines" in out and
       "python/src/Big.cpp: 840 lines" in out, "the size rules must cover apps/ and python/src", out)

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

for f in failures:
    print("FAILED: " + f)
print(f"{checks - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
