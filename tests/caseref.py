"""Case-file text shared by the CLI and validation tests (test_bearing_cli.py,
test_cli_io.py, test_distributed_faults.py, test_fem_sweep.py, test_report.py)."""
import json

#: The [bearing] table of a 209 deep-groove ball bearing (D 12.7 mm, 9 balls, pitch
#: diameter 65 mm, conformities 0.52), as a case file writes it.
BEARING_209 = """[bearing]
ball_diameter = "12.7 mm"
n_balls = 9
pitch_diameter = "65 mm"
f_inner = 0.52
f_outer = 0.52
"""


def case_header(cid, title, calculation, *, kind="independent derivation", author="x",
                year=2026, reference="synthetic"):
    """The keys every validation case starts with (validation/schema.py): the [[case]]
    table's id, title, kind, calculation and source, as TOML text."""
    def q(s):
        return json.dumps(s, ensure_ascii=False)

    return (f"[[case]]\nid = {q(cid)}\ntitle = {q(title)}\nkind = {q(kind)}\n"
            f"calculation = {q(calculation)}\n"
            f"source = {{ author = {q(author)}, year = {year}, reference = {q(reference)} }}\n")
