#!/usr/bin/python3
"""Checks that every #include points down the folder order (ctest layers_point_down).

The order, lowest first: model/common; model/scene and model/golden; the units' model folders
(model/improved, improved2, trad, halfspace: a unit may use another unit's stages); tb/common;
the units' tb folders; tb/fuzz (over every unit); app/. A file may include its own
layer and any lower one, never a higher one. tools/ and tests/ sit above everything.
  scripts/check_layers.py [ROOT]
Prints each include that points up and exits 1, or prints a summary and exits 0."""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
UNITS = ('improved', 'improved2', 'trad', 'halfspace')
LAYERS = [('model/common',), ('model/scene', 'model/golden'), tuple('model/' + u for u in UNITS),
          ('tb/common',), tuple('tb/' + u for u in UNITS), ('tb/fuzz',), ('app',)]
# The include roots (CMake's include directories) and the folders under them.
ROOTS = ('model', 'tb', 'app')


def layer_of(folder):
    for i, names in enumerate(LAYERS):
        if any(folder == n or folder.startswith(n + '/') for n in names):
            return i
    return None


def resolve(src_dir, name):
    """The repository folder an include names: relative to the file, else to an include root."""
    for base in [src_dir] + [os.path.join(ROOT, r) for r in ROOTS]:
        path = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(path):
            return os.path.relpath(os.path.dirname(path), ROOT)
    return None


bad = checked = 0
for top in ('model', 'tb', 'app'):
    for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
        for f in files:
            if not f.endswith(('.cpp', '.hpp', '.h')):
                continue
            path = os.path.join(dirpath, f)
            here = os.path.relpath(dirpath, ROOT)
            mine = layer_of(here)
            for n, line in enumerate(open(path, encoding='utf-8'), 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if not m:
                    continue
                target = resolve(dirpath, m.group(1))
                if target is None:
                    continue  # generated or external
                checked += 1
                theirs = layer_of(target)
                if mine is not None and theirs is not None and theirs > mine:
                    print(f'{os.path.relpath(path, ROOT)}:{n}: includes {m.group(1)} ({target}), a higher layer')
                    bad += 1
if bad:
    sys.exit(1)
print(f'check_layers: {checked} includes, every one points to its own layer or a lower one')
