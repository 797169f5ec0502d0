"""test_doc_examples_normalize.py SOURCE_DIR — scripts/doc_examples.py compares printed figures strictly (exactly, except
that a number printed with 15 or more significant digits, a %.17g round trip, need only agree to 1e-12 relative), and
in a second, cross-machine tier to 1e-3 relative, round-off figures (|x| < 1e-9) to a factor of 10, an element index
on a round-off line freely: what another x86-64 CPU moves. Checks that each tier forgives exactly that and nothing
coarser, and that the page's figures still fail to match a build whose figures moved. Standard library only; exit
status 1 on failure."""
import importlib.util
import sys

spec = importlib.util.spec_from_file_location("doc_examples", sys.argv[1] + "/scripts/doc_examples.py")
doc = importlib.util.module_from_spec(spec)
spec.loader.exec_module(doc)
failures = []


def same(page, build, portable=False):
    return doc.matches(doc.normalize_lines([page]), doc.normalize_lines([build]), portable)


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
# The cross-machine tier: (page, build, should match portably, why); every one of these fails strictly unless equal.
portable_cases = [
    ("e_G 2.7446e-03, max 2.1198e-02", "e_G 2.7469e-03, max 2.1198e-02", True, "e_G moved 8.4e-4 relative (AMD vs Intel)"),
    ("e_G 2.7446e-03", "e_G 2.7506e-03", False, "e_G moved 2.2e-3 relative"),
    ("8327 vertices, 16650 triangles", "8325 vertices, 16646 triangles", True, "2 of 8327 vertices"),
    ("8327 vertices", "8300 vertices", False, "27 of 8327 vertices"),
    ("Gauss-Bonnet residual -6.075e-13", "Gauss-Bonnet residual -5.578e-13", True, "round-off residuals"),
    ("Gauss-Bonnet residual -6.075e-13", "Gauss-Bonnet residual 4.1e-14", False, "a residual 15x smaller"),
    ("Gauss-Bonnet residual -6.075e-13", "Gauss-Bonnet residual -7.2e-12", False, "a residual 12x larger"),
    ("max |K - K^| 4.36e-11 rad", "max |K - K^| 2.1e-9 rad", False, "a residual above 1e-9"),
    ("max relative residual 9.356e-16 (edge 224)", "max relative residual 8.433e-16 (edge 812)", True,
     "the element where a round-off maximum sits"),
    ("length 0.5 (edge 224)", "length 0.5 (edge 812)", False, "an element index on a line without round-off figures"),
    ("target circle-domain, 7 Newton steps", "target circle-domain, 8 Newton steps", False, "a Newton step count"),
    ("area 3.01650788338", "area 3.01650805866", True, "an area moved 6e-8 relative"),
    ("genus 0, 1 boundary loops", "genus 1, 1 boundary loops", False, "a genus"),
]
for page, build, want, why in cases:
    if same(page, build) != want:
        failures.append(f"{why}: page '{page}' vs build '{build}' {'should' if want else 'should not'} match")
for page, build, want, why in portable_cases:
    if same(page, build) != (page == build):
        failures.append(f"{why}: page '{page}' vs build '{build}' strictly")
    if same(page, build, portable=True) != want:
        failures.append(f"{why}: page '{page}' vs build '{build}' {'should' if want else 'should not'} match portably")
for f in failures:
    print("FAIL", f)
print(f"{len(cases) + len(portable_cases)} normalization cases, {len(failures)} failures")
sys.exit(1 if failures else 0)
