#!/usr/bin/env python3
"""assemble.py TEMPLATE DATA.json OUT.html [--leaflet-dir DIR]

Reference implementation of what the C++ output layer does to write map.html:
literal (non-regex) replacement of the three placeholders of
src/output/maphtml/map_template.html, each of which must occur exactly once:

  /*LEAFLET_CSS*/  -> leaflet.css of Debian's libjs-leaflet (verbatim)
  /*LEAFLET_JS*/   -> leaflet.js of libjs-leaflet (verbatim)
  /*MAP_DATA*/     -> the map data, a JSON object, escaped for a <script>:
                      every '<' written as \\u003c (so neither '</script' nor
                      '<!--' can appear), U+2028/U+2029 as \\u2028/\\u2029;
                      NaN/Infinity are not JSON: write null instead.

The placeholders are located in the template first and the pieces joined, so a
placeholder-like string inside the inserted texts is never replaced again.
Leaflet's '$1'/'$2' sequences are harmless with literal replacement (they would
be expanded by std::regex_replace or JS String.replace). The trailing
'sourceMappingURL' comments of leaflet.js/.css are dropped (they point at .map
files that do not exist next to map.html; only DevTools would ask for them).
"""
import json
import os
import re
import sys

PLACEHOLDERS = ('/*LEAFLET_CSS*/', '/*LEAFLET_JS*/', '/*MAP_DATA*/')
DEFAULT_LEAFLET_DIR = '/usr/share/javascript/leaflet'


def escape_json_for_script(text):
    # '<' only occurs inside JSON strings, where \u003c is an equivalent escape.
    return text.replace('<', '\\u003c').replace('\u2028', '\\u2028').replace('\u2029', '\\u2029')


def strip_source_map(text):
    return re.sub(r'\n?(//[#@] sourceMappingURL=[^\n]*|/\*[#@] sourceMappingURL=[^*]*\*/)\s*$', '\n', text)


def leaflet_texts(leaflet_dir):
    with open(os.path.join(leaflet_dir, 'leaflet.css'), encoding='utf-8') as f:
        css = strip_source_map(f.read())
    with open(os.path.join(leaflet_dir, 'leaflet.js'), encoding='utf-8') as f:
        js = strip_source_map(f.read())
    if re.search(r'</style', css, re.I):
        raise SystemExit('leaflet.css contains </style')
    # Debian's leaflet.js 1.7.1 contains no '</script' and no '<!--'; be safe anyway
    # ('<\/' means the same as '</' in JS strings, regexes and comments).
    js = re.sub(r'</(script)', r'<\\/\1', js, flags=re.I).replace('<!--', '<\\!--')
    return css, js


def assemble(template, css, js, data_obj):
    data = escape_json_for_script(json.dumps(data_obj, ensure_ascii=False, allow_nan=False, separators=(',', ':')))
    pos = []
    for ph in PLACEHOLDERS:
        n = template.count(ph)
        if n != 1:
            raise SystemExit('template must contain %s exactly once (found %d)' % (ph, n))
        pos.append((template.index(ph), ph))
    repl = dict(zip(PLACEHOLDERS, (css, js, data)))
    out, last = [], 0
    for at, ph in sorted(pos):
        out.append(template[last:at])
        out.append(repl[ph])
        last = at + len(ph)
    out.append(template[last:])
    return ''.join(out)


def main(argv):
    args = [a for a in argv[1:] if not a.startswith('--leaflet-dir')]
    leaflet_dir = DEFAULT_LEAFLET_DIR
    for i, a in enumerate(argv):
        if a.startswith('--leaflet-dir='):
            leaflet_dir = a.split('=', 1)[1]
        elif a == '--leaflet-dir' and i + 1 < len(argv):
            leaflet_dir = argv[i + 1]
            args.remove(leaflet_dir)
    if len(args) != 3:
        raise SystemExit(__doc__)
    template_path, data_path, out_path = args
    with open(template_path, encoding='utf-8') as f:
        template = f.read()
    with open(data_path, encoding='utf-8') as f:
        data_obj = json.load(f)
    css, js = leaflet_texts(leaflet_dir)
    html = assemble(template, css, js, data_obj)
    with open(out_path, 'w', encoding='utf-8') as f:
        f.write(html)
    print('wrote %s (%d bytes)' % (out_path, len(html.encode('utf-8'))))


if __name__ == '__main__':
    main(sys.argv)
