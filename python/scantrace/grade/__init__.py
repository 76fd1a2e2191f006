"""scantrace.grade: the autograder of the course's triangle-filling assignment.

    python3 -m scantrace.grade SUBMISSION… [-o DIR] [--jobs N] [--rubric R.toml]
                               [--hidden-seed S] [--scene hw1.npy] [--module NAME] [--no-sandbox]

Runs the student's vector_interp, f_shading, g_shading and render_img in a bubblewrap sandbox
(sandbox.py; the child side is harness.py, numpy and the standard library only) on the battery
(battery.py: vector_interp cases, probe triangles, hidden scenes, the course scene), scores it by
the rubric (rubric.py, default_rubric.toml), names the mistakes as causes (causes.py, from the
models of fill_models.py and diagnose.py) and writes results.json in Gradescope's format,
report.md and report.html (report.py); a class gets class.csv and class.html (classmode.py).
docs/grading.md describes it.
"""
