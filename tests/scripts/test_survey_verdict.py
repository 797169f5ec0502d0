"""test_survey_verdict.py SOURCE_DIR CONFORMESH DATA_DIR — scripts/survey_cgal.py's verdict on the default route
(docs/robustness.md's summary): an exit 0 counts as ok only with its smallest angle >= min(20.7 deg, the input's
smallest angle sum), no inversion, Gauss-Bonnet and the input's area, also in the file read back; exit 1 is a refusal
only where info refuses the file too. Synthetic rows first, then the script itself on three files (hedra.off and
blobby_3cc.off, three components reported one by one: ok; degtri_sliding.off: refused). Standard library only; exit status 1 on any failure."""
import os
import subprocess
import sys
import tempfile

source, conformesh, data = sys.argv[1:4]
sys.path.insert(0, os.path.join(source, "scripts"))
import survey_cgal  # noqa: E402

failures = []


def expect(what, got, want):
    if got != want:
        failures.append("%s: got %r, want %r" % (what, got, want))


def row(status, info=0, bound=20.7048110546, **figures):
    f = {"vertices": 10, "min_angle": 30.0, "inverted": 0, "gauss_bonnet": 1e-13, "area": 1.0, "input_area": 1.0,
         "reread": (30.0, 1.0)}
    f.update(figures)
    r = {"mesh": "m.off", "info": (info, 0.0, ""), "input": (status, 0.0, "", f if status in (0, 3) else {})}
    if bound is not None:
        r["angle_bound"] = bound
    return r


expect("verified", survey_cgal.default_outcome(row(0)), "ok")
expect("angle below 20.7", survey_cgal.default_outcome(row(0, min_angle=20.0)), "failed")
# A cone of 8 deg bounds the output's angle by 8 deg: 8.0 is ok, 7.9 is not.
expect("angle at a sharp cone", survey_cgal.default_outcome(row(0, bound=8.0, min_angle=8.0, reread=(8.0, 1.0))),
       "ok")
expect("angle below a sharp cone", survey_cgal.default_outcome(row(0, bound=8.0, min_angle=7.9)), "failed")
expect("inverted", survey_cgal.default_outcome(row(0, inverted=1)), "failed")
expect("Gauss-Bonnet", survey_cgal.default_outcome(row(0, gauss_bonnet=1e-6)), "failed")
expect("area", survey_cgal.default_outcome(row(0, area=1.001)), "failed")
expect("written file's corner", survey_cgal.default_outcome(row(0, reread=(3.0, 1.0))), "failed")
expect("written file unreadable", survey_cgal.default_outcome(row(0, reread="error: bad file")), "failed")
expect("exit 3", survey_cgal.default_outcome(row(3)), "failed")
expect("exit 1 on valid input", survey_cgal.default_outcome(row(1)), "failed")
expect("exit 1 on input info refuses", survey_cgal.default_outcome(row(1, info=1, bound=None)), "refused")
expect("timeout", survey_cgal.default_outcome(row("timeout")), "failed")

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "robustness.md")
    p = subprocess.run([sys.executable, os.path.join(source, "scripts", "survey_cgal.py"), conformesh, "--data", data,
                        "--only", "hedra", "blobby_3cc", "degtri_sliding", "--no-check", "-o", out],
                       capture_output=True, text=True, timeout=120)
    expect("survey exit status", p.returncode, 0)
    text = open(out).read() if os.path.exists(out) else ""
    want = ("Default route (`conformesh remesh MESH`), 3 files: **ok 2** (exit 0, verified, angle bound met), "
            "**refused 1** (exit 1 on input that info refuses too), **failed 0**.")
    if want not in text:
        failures.append("survey summary: %r not in\n%s" % (want, text[:2000]))

for f in failures:
    print("FAIL " + f)
sys.exit(1 if failures else 0)
