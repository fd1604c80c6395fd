#!/usr/bin/env python3
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
# The structural rules of the package (issue 21), checked on include/:
#  1. internal/ is in layers that call only downward: core <- distances, borders, seams, atlas.
#     A layer includes headers of its own layer, of the layers below it, and leaf public
#     headers (public headers that include no internal header) only.
#  2. No documented public declaration, typedef or public base class names `internal::`:
#     outside function bodies, private and protected members, and \cond ... \endcond blocks of
#     the public headers.
#  3. Every function fits on a screen: at most MAX_LINES lines (default 60).
# Usage: check_structure.py [INCLUDE_DIR] [--max-lines N]. Exits 1 and lists every violation.
import os, re, sys

args = [a for a in sys.argv[1:] if not a.startswith('--')]
root = args[0] if args else os.path.join(os.path.dirname(__file__), '..', 'include')
max_lines = int(sys.argv[sys.argv.index('--max-lines') + 1]) if '--max-lines' in sys.argv else 60
package = os.path.join(root, 'CGAL', 'Surface_mesh_parameterization')
LAYERS = {'core': {'core'}, 'distances': {'core', 'distances'}, 'borders': {'core', 'borders'},
          'seams': {'core', 'seams'}, 'atlas': {'core', 'atlas'}}
INCLUDE = re.compile(r'#include\s*<CGAL/Surface_mesh_parameterization/([^>]+)>')
problems = []

def read(path):
    with open(path, errors='replace') as f:
        return f.read()

def package_includes(path):
    return INCLUDE.findall(read(path))

def code_only(text):
    """Comments and string literals blanked, line structure kept."""
    text = re.sub(r'/\*.*?\*/', lambda m: '\n' * m.group(0).count('\n'), text, flags=re.S)
    text = re.sub(r'//[^\n]*', '', text)
    return re.sub(r'"(\\.|[^"\\\n])*"', '""', text)

public = sorted(f for f in os.listdir(package) if f.endswith('.h'))
leaf = {f for f in public if not any(i.startswith('internal/') for i in package_includes(os.path.join(package, f)))}

# 1. layers
for layer in os.listdir(os.path.join(package, 'internal')):
    folder = os.path.join(package, 'internal', layer)
    if not os.path.isdir(folder):
        problems.append(f'internal/{layer}: a file outside the layers core, distances, borders, seams')
        continue
    for f in sorted(os.listdir(folder)):
        for inc in package_includes(os.path.join(folder, f)):
            parts = inc.split('/')
            if parts[0] == 'internal':
                if layer not in LAYERS or parts[1] not in LAYERS[layer]:
                    problems.append(f'internal/{layer}/{f}: includes internal/{parts[1]}/{parts[2]} (not a lower layer)')
            elif inc not in leaf:
                problems.append(f'internal/{layer}/{f}: includes the public header {inc}, which includes internal headers')

# 2 and 3: a walk over the code with the depth of braces, knowing which braces open functions.
CONTROL = re.compile(r'\b(if|for|while|switch|catch|do|else)\s*(\(.*)?$')
FUNCTION_HEAD = re.compile(r'\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(->\s*[\w:<>, ]+)?\s*$')
LAMBDA_HEAD = re.compile(r'(\]\s*(\([^()]*\))?\s*(mutable)?\s*|\]\s*\(.*\)\s*(mutable)?\s*)$')

def walk(path, public_header):
    raw = read(path)
    cond_lines = set()
    depth_cond = False
    for n, line in enumerate(raw.split('\n')):
        if '\\cond' in line:
            depth_cond = True
        if depth_cond:
            cond_lines.add(n)
        if '\\endcond' in line:
            depth_cond = False
    lines = code_only(raw).split('\n')
    stack, head = [], ''
    for n, line in enumerate(lines):
        in_function = any(e[0] == 'function' for e in stack)
        if stack and stack[-1][0] in ('class', 'struct'):
            access = re.match(r'\s*(public|private|protected)\s*:', line)
            if access:
                stack[-1] = (stack[-1][0], stack[-1][1], access.group(1) != 'public')
        hidden = any(len(e) > 2 and e[2] for e in stack)
        if public_header and not in_function and not hidden and n not in cond_lines and 'internal::' in line:
            problems.append(f'{os.path.relpath(path, root)}:{n + 1}: a public declaration names internal::')
        for ch in line:
            if ch == '{':
                statement = head.strip()
                last = re.split(r'[;}]', statement)[-1].strip()
                is_function = (not any(e[0] == 'function' for e in stack) and bool(FUNCTION_HEAD.search(last))
                               and not CONTROL.search(last) and not LAMBDA_HEAD.search(last)
                               and re.search(r'[~\w]+\s*\(', last) is not None)
                kind = re.match(r'.*\b(class|struct)\s+\w+[^()]*$', last)
                if is_function:
                    stack.append(('function', n))
                elif kind:
                    stack.append((kind.group(1), n, kind.group(1) == 'class'))
                else:  # a namespace internal is not documented
                    stack.append(('block', n, bool(re.search(r'namespace\s+internal$', last))))
                head = ''
            elif ch == '}':
                if stack:
                    kind, start = stack.pop()[:2]
                    if kind == 'function' and n - start + 1 > max_lines:
                        problems.append(f'{os.path.relpath(path, root)}:{start + 1}: a function of {n - start + 1} lines')
                head = ''
            elif ch == ';':
                head = ''
            else:
                head += ch
        head += ' '

for f in public:
    walk(os.path.join(package, f), True)
for layer in LAYERS:
    folder = os.path.join(package, 'internal', layer)
    for f in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        walk(os.path.join(folder, f), False)

for p in problems:
    print('check_structure:', p)
print(f'check_structure: {len(public)} public headers ({len(leaf)} leaves), '
      f'{sum(len(os.listdir(os.path.join(package, "internal", l))) for l in LAYERS if os.path.isdir(os.path.join(package, "internal", l)))} internal headers, '
      f'{len(problems)} problem(s)')
sys.exit(1 if problems else 0)
