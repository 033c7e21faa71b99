#!/usr/bin/env python3
"""Rewrite the README's figures table from the JSON lines of `make bench`.

Every bench line that carries "readme" (the row label) and "value" (the figure
as text, with its baseline or ratio) becomes one row, in the order the lines
came (the Makefile runs the benches in a fixed order; a label seen twice keeps
its first place and its last value). The table between the markers below is
replaced as a whole, so a figure no bench printed in this run disappears: a
stale number cannot survive a run.

    python3 bench/readme_figures.py build/bench.jsonl README.md
"""
import json
import sys
from pathlib import Path

BEGIN = "<!-- figures: written by `make bench` (bench/readme_figures.py) from its JSON lines -->"
END = "<!-- /figures -->"


def rows(lines):
    table = {}
    for line in lines:
        line = line.strip()
        if not line.startswith("{"):
            continue
        try:
            rec = json.loads(line)
        except ValueError:
            continue
        if isinstance(rec, dict) and "readme" in rec and "value" in rec:
            table[str(rec["readme"])] = str(rec["value"])   # dicts keep the first place
    return table


def render(table) -> str:
    out = ["| what | figure |", "|---|---|"]
    out += [f"| {k} | {v} |" for k, v in table.items()]
    return "\n".join(out)


def rewrite(readme: str, table) -> str:
    if BEGIN not in readme or END not in readme:
        raise SystemExit(f"readme_figures: the markers {BEGIN!r} ... {END!r} are missing")
    head, rest = readme.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{render(table)}\n{END}{tail}"


def main(argv) -> int:
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    table = rows(Path(argv[1]).read_text().splitlines())
    readme = Path(argv[2])
    readme.write_text(rewrite(readme.read_text(), table))
    print(f"readme_figures: {len(table)} rows written into {readme}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
