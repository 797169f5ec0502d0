"""test_doc_examples_normalize.py SOURCE_DIR — scripts/doc_examples.py compares printed figures exactly, except that a
number printed with 15 or more significant digits (a %.17g round trip) need only agree to 1e-12 relative: the last digits of such
numbers follow the BLAS kernels of the CPU. Checks that the rule forgives exactly that and nothing coarser, and that
the page's figures still fail to match a build whose figures moved. Standard library only; exit status 1 on failure."""
import importlib.util
import sys

spec = importlib.util.spec_from_file_location("doc_examples", sys.argv[1] + "/scripts/doc_examples.py")
doc = importlib.util.module_from_spec(spec)
spec.loader.exec_module(doc)
failures = []


def same(page, build):
    return doc.matches(doc.normalize_lines([page]), doc.normalize_lines([build]))


cases = [
    # (page, build, should match, why)
    ("0,0.49999999999997735,0.5091697834262644", "0,0.49999999999997735,0.50916978342652752", True,
     "17-digit figures that differ at 2e-13 relative (OpenBLAS kernels of another CPU)"),
    ("spin 0.5091697834262644", "spin 0.5091697834362644", False, "a 17-digit figure that moved at 2e-11 relative"),
    ("e_G 2.7424e-3", "e_G 2.7446e-3", False, "a short figure that moved in its 4th digit"),
    ("8330 vertices", "8327 vertices", False, "a count"),
    ("residual 7.4e-12", "residual 7.4e-12", True, "identical short figures"),
    ("area 43.082734134686751", "area 43.082734134686752", True, "last-digit noise in a 17-digit area"),
    ("area 43.082734134686751", "area 43.082734133686751", False, "a 17-digit area that moved at 2e-11"),
]
for page, build, want, why in cases:
    if same(page, build) != want:
        failures.append(f"{why}: page '{page}' vs build '{build}' {'should' if want else 'should not'} match")
for f in failures:
    print("FAIL", f)
print(f"{len(cases) - len(failures)}/{len(cases)} normalization cases as expected")
sys.exit(1 if failures else 0)
