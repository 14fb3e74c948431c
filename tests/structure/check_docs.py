#!/usr/bin/env python3
"""The README stays a front page that tells the truth about the code:
- it fits on a few screens (at most 250 lines);
- every line of its C++ snippet (trailing comments aside) is a line of the demo it names (demos/GliderSimpleSetupDemo.cpp, built and run by
  ctest), every line of its Python snippet a line of docs/PYTHON.md's example;
- the two quick-start commands are the scripts that exist;
- no "issue N" in the user-facing text (README, docs/);
- every relative link of the README and of docs/*.md points at a file or folder that exists.
Usage: check_docs.py SOURCE_DIR"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.')
errors = []
readme = (root / 'README.md').read_text()


def blocks(text, lang):
    return re.findall(r'^```' + lang + r'\n(.*?)^```', text, re.S | re.M)


def code_lines(block, comment):
    for line in block.splitlines():
        s = line.strip()
        if s and not s.startswith(comment):
            yield s


n = readme.count('\n')
if n > 250:
    errors.append(f'README.md: {n} lines, more than 250: move details to docs/')

cpp = blocks(readme, 'cpp')
demo = {l.split('//')[0].strip() for l in (root / 'demos/GliderSimpleSetupDemo.cpp').read_text().splitlines()}
if len(cpp) != 1:
    errors.append(f'README.md: {len(cpp)} C++ snippets, expected 1')
for line in code_lines(cpp[0] if cpp else '', '//'):
    if line.split('//')[0].strip() not in demo:  # a trailing comment may differ
        errors.append(f'README.md C++ snippet: "{line}" is not a line of demos/GliderSimpleSetupDemo.cpp')

py = blocks(readme, 'python')
doc = '\n'.join(blocks((root / 'docs/PYTHON.md').read_text(), 'python'))
doc_lines = {l.strip() for l in doc.splitlines()}
if len(py) != 1:
    errors.append(f'README.md: {len(py)} Python snippets, expected 1')
for line in code_lines(py[0] if py else '', '#'):
    if line not in doc_lines:
        errors.append(f'README.md Python snippet: "{line}" is not a line of docs/PYTHON.md\'s example')

for script in ('scripts/run_main.sh', 'scripts/run_tests.sh'):
    if f'bash {script}' not in readme or not (root / script).is_file():
        errors.append(f'README.md: the quick start must run `bash {script}` (and the script must exist)')

pages = [root / 'README.md'] + sorted((root / 'docs').glob('*.md'))
for page in pages:
    text = page.read_text()
    for i, line in enumerate(text.splitlines(), 1):
        if re.search(r'\bissue #?\d', line, re.I):
            errors.append(f'{page.relative_to(root)}:{i}: "issue N" in user-facing text')
    for target in re.findall(r'\]\(([^)\s]+)\)', text):
        if re.match(r'[a-z]+:', target) or target.startswith('#'):
            continue
        path = (page.parent / target.split('#')[0]).resolve()
        if not path.exists():
            errors.append(f'{page.relative_to(root)}: link to {target}: no such file')

for e in errors:
    print(e)
print('docs check:', 'FAILED' if errors else f'ok ({len(pages)} pages)')
sys.exit(1 if errors else 0)
