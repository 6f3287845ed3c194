#!/usr/bin/python3
"""The allowed include directions between the modules of lib/, read from the module table of
docs/architecture.md (the one source of the layering).

    include_rules.py SOURCE_DIR

Reads every `#include "module/..."` of lib/<module>/ and fails (exit 1) on an include of a
module that is not in ALLOWED[module], and on a deal.II, gmsh or PETSc header in the
interface or sources of a light module (the layers that build and test without deal.II).
The ParameterHandler bindings (parameters.h/.cc) of a light module are compiled into a
separate *_params target and may use deal.II in their .cc only.
"""
import os, re, sys

def read_layering(source_dir):
    """module -> (modules it may include, {part prefix: modules allowed only in that part}),
    from the module table of docs/architecture.md (its last column; transitive; None for
    "everything"). A cell "a, b; relief: c" allows c only in lib/<module>/relief*, a cell part
    "gearbox/fe: c" only under lib/gearbox/fe/."""
    direct, parts = {}, {}
    for line in open(os.path.join(source_dir, 'docs', 'architecture.md'), encoding='utf-8'):
        m = re.match(r'^\| `([a-z_]+)` \|.*\| ([^|]*) \|\s*$', line)
        if not m:
            continue
        module, cell = m.group(1), m.group(2).strip()
        if cell == 'everything':
            direct[module] = None
            continue
        chunks = [c.strip() for c in cell.split(';')]
        names = lambda text: {w.strip().split(' ')[0] for w in text.split(',') if w.strip() not in ('', '—')}
        direct[module] = names(chunks[0]) if chunks[0] != '—' else set()
        parts[module] = {}
        for c in chunks[1:]:
            part, _, deps = c.partition(':')
            part = part.strip()
            prefix = part + '/' if '/' in part else module + '/' + part
            parts[module][prefix] = names(deps)

    def closure(deps, seen):
        out = set()
        for d in deps:
            if d in seen or d not in direct:
                out.add(d)
                continue
            out.add(d)
            if direct[d] is not None:
                out |= closure(direct[d].union(*parts.get(d, {}).values()), seen | {d})
        return out

    allowed, only = {}, {}
    for module, deps in direct.items():
        if deps is None:
            allowed[module] = None
            continue
        allowed[module] = closure(deps, {module}) - {module}
        for prefix, pdeps in parts[module].items():
            extra = closure(pdeps, {module}) - allowed[module] - {module}
            for d in extra:
                only[(module, d)] = prefix
            allowed[module] |= extra
    return allowed, only


ALLOWED, SUBMODULE_ONLY = read_layering(sys.argv[1] if len(sys.argv) > 1 else '.')
# Modules (or their light parts) that must not see deal.II, gmsh or PETSc.
LIGHT = {'base', 'io', 'geometry', 'analytical', 'rating', 'calibration', 'dynamics', 'gearbox', 'optimise', 'shafts'}
# Files of light modules that are heavy by design: ParameterHandler bindings (their own
# targets), the optimiser's FE-in-the-loop tip-relief part, the gearbox FE stress source.
HEAVY_FILES = re.compile(r'(^|/)(parameters|relief[a-z_]*)\.(h|cc)$|^gearbox/fe/')
heavy_header = re.compile(r'#include\s*<(deal\.II/|gmsh|petsc|mpi\.h)')

root = os.path.join(sys.argv[1] if len(sys.argv) > 1 else '.', 'lib')
bad = []
edges = 0
for module in sorted(os.listdir(root)):
    mdir = os.path.join(root, module)
    if not os.path.isdir(mdir):
        continue
    if module not in ALLOWED:
        bad.append(f'lib/{module}: a module folder that docs/architecture.md does not list')
        continue
    for dirpath, _, names in os.walk(mdir):
        for n in names:
            if not n.endswith(('.h', '.cc')):
                continue
            path = os.path.join(dirpath, n)
            rel = os.path.relpath(path, root)
            text = open(path, encoding='utf-8').read()
            for m in re.finditer(r'#include\s+"([a-z_]+)/', text):
                dep = m.group(1)
                edges += 1
                if dep == module or ALLOWED[module] is None:
                    continue
                if dep not in ALLOWED[module]:
                    bad.append(f'lib/{rel}: includes {dep}/, not allowed for {module}')
                elif (module, dep) in SUBMODULE_ONLY and not rel.startswith(SUBMODULE_ONLY[(module, dep)]):
                    bad.append(f'lib/{rel}: includes {dep}/, allowed only in lib/{SUBMODULE_ONLY[(module, dep)]}*')
            sub = os.path.relpath(path, root)
            if module in LIGHT and not HEAVY_FILES.search(sub) and heavy_header.search(text):
                bad.append(f'lib/{rel}: a deal.II/gmsh/PETSc/MPI header in the light module {module}')
            if module in LIGHT and HEAVY_FILES.search(sub) and n.endswith('.h') and heavy_header.search(text):
                bad.append(f'lib/{rel}: a deal.II header in the interface of {module} (forward-declare it)')
for b in bad:
    print('include rule:', b)
print(f'include_rules: {edges} includes checked, {len(bad)} violations')
sys.exit(1 if bad else 0)
