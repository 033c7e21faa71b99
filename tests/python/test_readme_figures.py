"""`make bench` writes the README's figures table (issue 16, item 7): rows from the
bench lines carrying "readme" and "value", in their order, and nothing else."""
import importlib.util
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("readme_figures", ROOT / "bench" / "readme_figures.py")
rf = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rf)


def lines(*recs):
    return [json.dumps(r) for r in recs] + ["not json", "{broken"]


def test_rows_in_order_last_value_wins_others_ignored():
    t = rf.rows(lines({"bench": "a", "readme": "fit", "value": "3 ms"},
                      {"bench": "b", "median_ms": 1.0},
                      {"bench": "c", "readme": "hermite", "value": "38 us"},
                      {"bench": "a", "readme": "fit", "value": "2.5 ms"}))
    assert list(t.items()) == [("fit", "2.5 ms"), ("hermite", "38 us")]


def test_the_table_is_replaced_whole_so_stale_rows_go():
    readme = f"intro\n{rf.BEGIN}\n| what | figure |\n|---|---|\n| old | 17x |\n{rf.END}\nrest\n"
    out = rf.rewrite(readme, {"new": "21x"})
    assert "| new | 21x |" in out and "old" not in out and "17x" not in out
    assert out.startswith("intro\n") and out.endswith(f"{rf.END}\nrest\n")
    assert rf.rewrite(out, {"new": "21x"}) == out          # idempotent


def test_the_readme_has_the_markers_and_only_bench_rows_between_them():
    text = (ROOT / "README.md").read_text()
    assert text.count(rf.BEGIN) == 1 and text.count(rf.END) == 1
    table = text.split(rf.BEGIN, 1)[1].split(rf.END, 1)[0].strip().splitlines()
    assert table[:2] == ["| what | figure |", "|---|---|"] and len(table) > 2


def test_missing_markers_are_an_error():
    with pytest.raises(SystemExit):
        rf.rewrite("no table here\n", {"x": "y"})
