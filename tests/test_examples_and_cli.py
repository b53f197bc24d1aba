"""Examples run, the CLI prints and fails cleanly."""

import runpy
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_seed_examples_script_prints_the_published_values():
    mod = runpy.run_path(str(ROOT / "examples" / "seed_worked_examples.py"))
    rows = list(mod["rows"]())
    for label, published, ours in rows:
        if label.startswith("000 ex.4"):
            continue  # the seed stopped iterating early; see tests/cable/test_catenary.py
        for pub, our in zip(published.split(), ours.split(), strict=False):
            decimals = len(pub.split(".")[1]) if "." in pub else 0
            assert round(float(our), decimals) == float(pub), (label, pub, our)


def run(*args):
    return subprocess.run([sys.executable, "-m", "skcable", *args], capture_output=True, text=True)


def test_cli_demo_and_json():
    assert run("demo").returncode == 0
    out = run("catenary", "--span", "800", "--dh", "-20", "--w", "20", "--low", "-30", "--json")
    assert out.returncode == 0 and '"H": 85819.2' in out.stdout


def test_cli_bad_argument_is_one_line_exit_2():
    out = run("catenary", "--span", "800", "--w", "20", "--length", "10")
    assert out.returncode == 2
    assert out.stderr.strip().count("\n") == 0 and "length" in out.stderr and "Traceback" not in out.stderr


def test_strand_bending_example_writes_figures_and_tables(tmp_path):
    mod = runpy.run_path(str(ROOT / "examples" / "strand_bending_law.py"))
    written = mod["figures"](tmp_path)
    assert len(written) == 3 and all(p.stat().st_size > 10_000 for p in written)
    table = mod["tables"]()
    assert "| 0.5 | 3.98e-05 |" in table  # the thesis value is shown beside ours
