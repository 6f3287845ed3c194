#!/usr/bin/python3
"""The allowed include directions between the modules of lib/ (docs/architecture.md).

    include_rules.py SOURCE_DIR

Reads every `#include "module/..."` of lib/<module>/ and fails (exit 1) on an include of a
module that is not in ALLOWED[module], and on a deal.II, gmsh or PETSc header in the
interface or sources of a light module (the layers that build and test without deal.II).
The ParameterHandler bindings (parameters.h/.cc) of a light module are compiled into a
separate *_params target and may use deal.II in their .cc only.
"""
import os, re, sys

# module -> modules it may include (besides itself). Data flows one way:
# geometry -> mesh -> fem -> contact -> loading -> post -> solve, with analytical/rating
# beside the FE chain, calibration and dynamics above the tables, the studies above solve.
light_base = {'base'}
ALLOWED = {
    'base': set(),
    'params': {'base'},
    'io': {'base'},
    'geometry': {'base', 'params'},
    'analytical': {'base', 'params', 'geometry'},
    'rating': {'base', 'params', 'geometry', 'analytical'},
    'calibration': {'base', 'params', 'geometry', 'analytical', 'io'},
    'dynamics': {'base', 'params', 'geometry', 'analytical', 'io'},
    'mesh': {'base', 'params', 'geometry'},
    'fem': {'base', 'params', 'geometry', 'mesh'},
    'contact': {'base', 'params', 'geometry', 'mesh', 'fem'},
    'loading': {'base', 'params', 'geometry', 'mesh', 'fem', 'contact'},
    'post': {'base', 'params', 'io', 'geometry', 'analytical', 'mesh', 'fem', 'contact', 'loading'},
    'solve': {'base', 'params', 'io', 'geometry', 'analytical', 'mesh', 'fem', 'contact', 'loading', 'post'},
    'choice': {'base', 'params', 'io', 'geometry', 'analytical', 'mesh', 'fem', 'contact', 'loading', 'post', 'solve',
               'condensed'},
    'condensed': {'base', 'params', 'io', 'geometry', 'analytical', 'calibration', 'mesh', 'fem', 'contact',
                  'loading', 'post', 'solve'},
    'optimise': {'base', 'params', 'io', 'geometry', 'analytical', 'mesh', 'fem', 'contact', 'loading', 'post',
                 'solve', 'condensed'},
    'gearbox': {'base', 'params', 'io', 'geometry', 'analytical', 'rating', 'solve'},
    'batch': {'base', 'params', 'io', 'geometry', 'mesh', 'fem', 'contact', 'loading', 'post', 'solve', 'condensed'},
    'tolerance': {'base', 'params', 'io', 'geometry', 'analytical', 'calibration', 'dynamics', 'mesh', 'fem',
                  'contact', 'loading', 'post', 'solve', 'condensed'},
    'helical': {'base', 'params', 'io', 'geometry', 'analytical', 'calibration', 'mesh', 'fem', 'contact',
                'loading', 'post', 'solve', 'condensed'},
    'exchange': {'base', 'params', 'io'},
    'commands': None,  # wires everything together
}
# Modules (or their light parts) that must not see deal.II, gmsh or PETSc.
LIGHT = {'base', 'io', 'geometry', 'analytical', 'rating', 'calibration', 'dynamics', 'gearbox', 'optimise'}
# Files of light modules that are heavy by design: ParameterHandler bindings (their own
# targets), the optimiser's FE-in-the-loop tip-relief part, the gearbox FE stress source.
HEAVY_FILES = re.compile(r'(^|/)(parameters|relief[a-z_]*)\.(h|cc)$|^gearbox/fe/')
# The FE stress source of the gearbox (gearbox/fe) may use the solve chain; the rest of
# gearbox may not.
SUBMODULE_ONLY = {('gearbox', 'solve'): 'gearbox/fe/'}
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
                    bad.append(f'lib/{rel}: includes {dep}/, allowed only in lib/{SUBMODULE_ONLY[(module, dep)]}')
            sub = os.path.relpath(path, root)
            if module in LIGHT and not HEAVY_FILES.search(sub) and heavy_header.search(text):
                bad.append(f'lib/{rel}: a deal.II/gmsh/PETSc/MPI header in the light module {module}')
            if module in LIGHT and HEAVY_FILES.search(sub) and n.endswith('.h') and heavy_header.search(text):
                bad.append(f'lib/{rel}: a deal.II header in the interface of {module} (forward-declare it)')
for b in bad:
    print('include rule:', b)
print(f'include_rules: {edges} includes checked, {len(bad)} violations')
sys.exit(1 if bad else 0)
