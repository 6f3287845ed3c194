#!/usr/bin/python3
"""Compare gearfem output files of two folders column by column.

    compare_outputs.py DIR_A DIR_B FILE...   (CSV files, or HDF5 files read with h5py)

Each column's largest difference relative to the column's largest magnitude must be at
most TOL (environment, default 1e-8); the wall time column "time [s]" is skipped (in CSV
files and HDF5 datasets). Columns that only B has (added to the contract since A was written)
are listed and not compared; a column of A missing in B is an error. Text columns and text datasets must be equal, except those named
in TEXT_SKIP (environment, comma-separated column names, e.g. "clause" when only the wording
of a citation changed). Columns
that are round-off diagnostics (the Lagrange complementarity residual and the penetration,
~1e-16 and ~1e-15 um when converged) are scaled by an absolute floor instead of their own
magnitude: their values are noise, and a change of summation order changes them by O(1).
Iteration counts (geometry and active-set iterations) may differ by one per row: a stopping
test that lands one iteration earlier within the same tolerance (e.g. the rotation floor of
lib/contact/two_body.cc) changes the count, not the result; a difference of two or more
counts as usual.
Prints the worst columns; exit status 1 if any exceeds TOL.
"""
import csv, sys, os
a, b = sys.argv[1], sys.argv[2]
files = sys.argv[3:]
text_skip = set(filter(None, os.environ.get('TEXT_SKIP', '').split(',')))
worst = {}
floor = {'complementarity [-]': 1e-6, 'max penetration [um]': 1e-3}
counts = {'geometry iterations [-]', 'active-set iterations [-]'}
for name in files:
    pa, pb = os.path.join(a, name), os.path.join(b, name)
    if name.endswith('.h5'):
        import h5py
        fa, fb = h5py.File(pa, 'r'), h5py.File(pb, 'r')
        def walk(g, prefix=''):
            for k in g:
                if isinstance(g[k], h5py.Dataset): yield prefix + k
                else: yield from walk(g[k], prefix + k + '/')
        for k in walk(fa):
            import numpy as np
            if k.split('/')[-1] == 'time [s]':
                continue
            x, y = np.asarray(fa[k]).ravel(), np.asarray(fb[k]).ravel()
            assert x.shape == y.shape, (name, k)
            if x.dtype.kind not in 'fiu':
                worst[name + ':' + k] = 0.0 if np.array_equal(x, y) or k.split('/')[-1] in text_skip else 1.0
                continue
            leaf = k.split('/')[-1]
            scale = max(float(np.abs(x).max()) if x.size else 0.0, floor.get(leaf, 1e-30))
            diff = np.abs(x - y)
            if leaf in counts and x.size and diff.max() <= 1:
                diff = np.zeros(0)
            d = float(diff.max() / scale) if diff.size else 0.0
            worst[name + ':' + k] = d
        continue
    ra, rb = list(csv.reader(open(pa))), list(csv.reader(open(pb)))
    # Every column of A must be in B, in A's order; columns B adds at the contract's later
    # versions (e.g. the friction columns) are listed, not compared.
    missing = [h for h in ra[0] if h not in rb[0]]
    assert not missing, (name, 'columns missing in', b, missing)
    added = [h for h in rb[0] if h not in ra[0]]
    if added:
        print(f'{name}: columns only in {b}, not compared: {", ".join(added)}')
    assert len(ra) == len(rb), (name, len(ra), len(rb))
    for i, h in enumerate(ra[0]):
        if h == 'time [s]': continue
        j = rb[0].index(h)
        try:
            col_a = [float(r[i]) for r in ra[1:]]; col_b = [float(r[j]) for r in rb[1:]]
        except ValueError:
            same = [r[i] for r in ra[1:]] == [r[j] for r in rb[1:]]
            worst[name + ':' + h] = 0.0 if same or h in text_skip else 1.0
            continue
        scale = max([abs(x) for x in col_a] + [floor.get(h, 1e-30)])
        diffs = [abs(x - y) for x, y in zip(col_a, col_b)]
        if h in counts and max(diffs + [0.0]) <= 1:
            diffs = [0.0]
        d = max([x / scale for x in diffs] + [0.0])
        worst[name + ':' + h] = d
tol = float(os.environ.get('TOL', '1e-8'))
bad = {k: v for k, v in worst.items() if v > tol}
for k, v in sorted(worst.items(), key=lambda kv: -kv[1])[:8]:
    print(f'{v:.3e}  {k}')
print('columns compared:', len(worst), 'over tolerance', tol, ':', len(bad))
sys.exit(1 if bad else 0)
