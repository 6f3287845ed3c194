"""The Python module gearfem against the CLI (tests/python, quick tier: ctest python_module).

References: `gearfem solve` and `gearfem solve --condensed` of the same input, run here as
processes (results.h5 holds the tables at full precision; the CSV files at 10 significant
digits); the cycle file written, read and written again; the exit-status contract of the CLI
(bad input: a named InputError; a solver failure: SolverError with its reason).
"""
import os
import subprocess
import threading
import time

import h5py
import numpy as np
import pytest

import gearfem

SRC = os.environ.get("GEARFEM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
GEARFEM = os.environ.get("GEARFEM", os.path.join(SRC, "build", "app", "gearfem"))
# The tiny study of the quick batch tests: 3-tooth sectors of a 20/40 pair, 5 positions, 2 torques.
STUDY = os.path.join(SRC, "tests", "regression", "data", "batch", "study.prm")


def cli(*args):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    r = subprocess.run([GEARFEM, *args], capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stdout + r.stderr
    return r


def h5_table(folder, name):
    with h5py.File(os.path.join(folder, "results.h5"), "r") as f:
        g = f[name]
        return {k: np.asarray(g[k]) for k in g}


def same_tables(py_table, h5_group, tol=1e-12):
    """Every column of the module's table equals the file's to tol of the column's scale
    (the wall time aside). The HDF5 datasets are named as the CSV columns."""
    assert py_table, "empty table"
    for key, values in py_table.items():
        name = key.rsplit(" [", 1)[0]
        if name == "time":
            continue
        ref = h5_group[key.replace("/", " per ")]  # HDF5 names cannot hold '/'

        assert ref.shape == values.shape, key
        scale = max(float(np.abs(ref).max()) if ref.size else 0.0, 1e-300)
        if name in ("complementarity", "max penetration"):
            scale = max(scale, 1e-6)  # round-off diagnostics (tests/regression/compare_outputs.py)
        assert float(np.abs(values - ref).max() / scale) <= tol if ref.size else True, key


@pytest.fixture(scope="module")
def study():
    return gearfem.read_input(STUDY)


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory, study):
    out = str(tmp_path_factory.mktemp("cli"))
    cli("solve", STUDY, "--output-dir", out)
    return out


def test_solve_equals_the_cli(study, cli_run):
    r = gearfem.solve(study)
    assert r.route == "full FE"
    same_tables(r.sweep, h5_table(cli_run, "sweep"))
    same_tables(r.pairs, h5_table(cli_run, "pairs"))
    assert r.run["route"]["name"] == "full FE"
    # The CSV file holds 10 significant digits.
    csv = np.genfromtxt(os.path.join(cli_run, "sweep.csv"), delimiter=",", names=True)
    ste = r.sweep["STE [um]"]
    assert np.allclose(csv["STE_um"], ste, rtol=1e-9, atol=0)


def test_cycle_solve_equals_the_cli(tmp_path, study):
    cycle_dir, on_cycle = str(tmp_path / "cycle"), str(tmp_path / "on_cycle")
    cli("condense", STUDY, "--output-dir", cycle_dir)
    cfile = os.path.join(cycle_dir, "condensed.h5")
    cli("solve", STUDY, "--condensed", cfile, "--output-dir", on_cycle)
    ref_sweep, ref_pairs = h5_table(on_cycle, "sweep"), h5_table(on_cycle, "pairs")
    # The CLI's cycle, loaded, and a cycle built here from the same input.
    for cyc in (gearfem.load_cycle(cfile), gearfem.condense(study)):
        r = cyc.solve(torques=[100.0, 200.0])
        assert r.route == "condensed cycle"
        same_tables(r.sweep, ref_sweep)
        same_tables(r.pairs, ref_pairs)


def test_save_and_load_round_trip_bit_for_bit(tmp_path, study):
    cyc = gearfem.condense(study)
    a, b = str(tmp_path / "a.h5"), str(tmp_path / "b.h5")
    cyc.save(a)
    loaded = gearfem.load_cycle(a)
    loaded.save(b)
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        names = []
        fa.visit(names.append)
        for n in names:
            if isinstance(fa[n], h5py.Dataset):
                assert np.array_equal(np.asarray(fa[n]), np.asarray(fb[n])), n
            for k, v in fa[n].attrs.items():
                assert np.array_equal(v, fb[n].attrs[k]), (n, k)
        for k, v in fa.attrs.items():
            if k != "created":
                assert v == fb.attrs[k], k
    r1, r2 = cyc.solve(torques=[150.0]), loaded.solve(torques=[150.0])
    for k in r1.sweep:
        if not k.startswith("time"):
            assert np.array_equal(r1.sweep[k], r2.sweep[k]), k


def test_variants_on_the_cycle(study):
    cyc = gearfem.condense(study)
    plain = cyc.solve(torques=[200.0])
    relief = cyc.solve(torques=[200.0], relief={"Gear 1/Tip relief": "linear", "Gear 1/Tip relief amount": 10,
                                                "Gear 1/Tip relief length": 2})
    # A relief separates the flanks near the tip: the mean STE grows (more rotation per torque).
    assert relief.sweep["STE [um]"].mean() > plain.sweep["STE [um]"].mean()
    lo, hi = cyc.torque_range
    assert lo <= 100.0 and hi >= 200.0


def test_bad_input_raises_the_named_error(study):
    with pytest.raises(gearfem.InputError, match="Solve/Torques") as e:
        study.set({"Solve/Torques": -5})
    assert isinstance(e.value, ValueError)
    with pytest.raises(gearfem.InputError, match="Tip relief amunt"):
        study.set({"Gear 1/Tip relief amunt": 5})
    with pytest.raises(gearfem.InputError, match="input file"):
        gearfem.read_input("/nonexistent.prm")
    cyc = gearfem.condense(study)
    with pytest.raises(gearfem.InputError, match="torque range of the condensed cycle"):
        cyc.solve(torques=[1e6])


def test_a_solver_failure_raises_solver_error():
    bad = gearfem.read_input(os.path.join(SRC, "inputs", "bad", "solve", "no_contact.prm"))
    with pytest.raises(gearfem.SolverError, match="no contact found") as e:
        gearfem.solve(bad)
    assert isinstance(e.value, RuntimeError)


def test_silent_by_default_progress_on_request_and_the_gil_released(study, capfd):
    gearfem.solve(study)
    assert capfd.readouterr().out == ""
    lines = []
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.01)

    t = threading.Thread(target=tick)
    t.start()
    gearfem.solve(study, progress=lines.append)
    stop.set()
    t.join()
    assert any(line.startswith("position ") and "/10" in line for line in lines), lines[:5]
    assert len(ticks) > 5  # the other thread ran during the solve


def test_kinematics_draws_and_ratings(study):
    p = gearfem.pair(study)
    assert p["teeth"] == (20, 40)
    assert 1.4 < p["contact ratio"] < 1.8
    assert len(p["gear 1"]["x [mm]"]) > 100
    graded = study.set({"Deviations/Accuracy grade": 6, "Deviations/Seed": 3})
    d0, d1 = gearfem.deviation_draws(graded, 0), gearfem.deviation_draws(graded, 1)
    f0 = d0["gear 1"]["f_pt [um]"]
    assert len(f0) == 20 and abs(f0.sum()) < 1e-9  # single pitch deviations close the circle
    assert not np.array_equal(f0, d1["gear 1"]["f_pt [um]"])
    rating = gearfem.rate(study)
    assert len(rating["torques [N m]"]) >= 1


def test_helical_on_its_shafts_equals_the_cli(tmp_path):
    # gearfem.helical takes the route `gearfem helical` takes (system_deflection::run_job): on
    # the shafts with System/Coupling = shafts. Reference: the CLI's helical.json and system.json
    # of the same input (10 significant digits).
    import json
    case = os.path.join(SRC, "inputs", "system_overhung.prm")
    prm = tmp_path / "case.prm"
    prm.write_text(open(case).read() + (
        "subsection Solve\n  set Number of positions = 8\n  set Torques = 100, 200\n  set Plots = false\nend\n"))
    out = tmp_path / "cli"
    cli("helical", str(prm), "--output-dir", str(out))
    with open(out / "helical.json") as f:
        ref = {t["torque_Nm"]: t for t in json.load(f)["torques"]}
    with open(out / "system.json") as f:
        sysj = json.load(f)
    iso = {t["torque_Nm"]: t for t in sysj["torques"]}
    res = gearfem.helical(gearfem.read_input(str(prm)))
    assert [r["torque [N m]"] for r in res] == [100.0, 200.0]
    for r in res:
        T = r["torque [N m]"]
        assert abs(r["K_Hbeta"] / ref[T]["k_h_beta"] - 1) < 1e-9
        assert abs(r["STE mean [um]"] / ref[T]["ste_mean_um"] - 1) < 1e-9
        assert abs(r["K_Hbeta ISO method C"] / iso[T]["k_h_beta_iso_method_c"] - 1) < 1e-9
        assert abs(r["correction slope [um]"] / sysj["correction_slope_um"] - 1) < 1e-9
        assert r["K_Hbeta"] > 1.0  # the shafts bend: not the aligned face


def test_system_equals_the_cli(tmp_path):
    # gearfem.system runs `gearfem system` in the library (the two-stage train at one torque).
    # Reference: the CLI's stage_<k>/helical.json and bearings.csv of the same input.
    import csv
    import json
    case = os.path.join(SRC, "inputs", "system_two_stage.prm")

    def stage(k):  # the stage on a coarse mesh, 6 positions and 7 slices (quick)
        p = tmp_path / f"stage_{k}.prm"
        p.write_text(open(os.path.join(SRC, "inputs", f"system_two_stage_{k}.prm")).read() +
                     "subsection Solve\n  set Number of positions = 6\nend\n"
                     "subsection Mesh\n  set h_contact = 0.3\n  set h_fillet = 0.5\n  set h_body = 6\nend\n"
                     "subsection Helical\n  set Slices = 7\nend\n")
        return str(p)
    prm = tmp_path / "train.prm"
    prm.write_text(open(case).read() + "subsection Train\n  set Torques = 200\n" + "".join(
        f"  subsection Stage {k}\n    set Input = {stage(k)}\n  end\n" for k in (1, 2)) + "end\n")
    out = tmp_path / "cli"
    cli("system", str(prm), "--output-dir", str(out))
    res = gearfem.system(gearfem.read_input(str(prm)))
    assert list(res["ratio"]) == [1.0, 3.0]
    for k in (1, 2):
        with open(out / f"stage_{k}" / "helical.json") as f:
            ref = json.load(f)["torques"][0]
        got = res["stages"][k - 1][0]
        assert got["torque [N m]"] == ref["torque_Nm"]
        assert abs(got["K_Hbeta"] / ref["k_h_beta"] - 1) < 1e-9
        assert abs(got["STE mean [um]"] / ref["ste_mean_um"] - 1) < 1e-9
    with open(out / "bearings.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(res["bearings"]["F_x [N]"]) == 6
    for r, fx, fy in zip(rows, res["bearings"]["F_x [N]"], res["bearings"]["F_y [N]"]):
        assert abs(float(r["F_x_N"]) - fx) <= 1e-9 * max(1.0, abs(fx))
        assert abs(float(r["F_y_N"]) - fy) <= 1e-9 * max(1.0, abs(fy))
