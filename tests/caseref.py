"""Case-file text shared by the CLI tests (test_bearing_cli.py, test_cli_io.py)."""

#: The [bearing] table of a 209 deep-groove ball bearing (D 12.7 mm, 9 balls, pitch
#: diameter 65 mm, conformities 0.52), as a case file writes it.
BEARING_209 = """[bearing]
ball_diameter = "12.7 mm"
n_balls = 9
pitch_diameter = "65 mm"
f_inner = 0.52
f_outer = 0.52
"""
