"""test_script_dependencies.py PYTHON SOURCE_DIR BUILD_DIR — the Python scripts that conformesh runs (plot_convergence,
plot_layout, render_mesh) under an interpreter that lacks numpy or matplotlib exit non-zero with one message naming the
missing module and the Debian package that provides it, never a traceback; the build's copies (installed as they are)
have PYTHON, CMake's CONFORMESH_PYTHON, as their shebang. Standard library only; exit status 1 on any failure."""
import os
import subprocess
import sys
import tempfile

python, source, build = sys.argv[1:4]
scripts = ["plot_convergence", "plot_layout", "render_mesh"]
failures = []


def expect_missing(script, argv, env, module, package):
    r = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=60)
    ok = (r.returncode != 0 and f"no Python module '{module}'" in r.stderr and f"apt-get install {package}" in r.stderr
          and "Traceback" not in r.stderr and r.stderr.count("\n") == 1)
    if not ok:
        failures.append(f"{script} without {module}: status {r.returncode}, stderr:\n{r.stderr}")


# No site-packages at all (-S; -I drops PYTHONPATH and the user site): numpy, imported first where used, is missing.
first = {"plot_convergence": "numpy", "plot_layout": "matplotlib", "render_mesh": "numpy"}
for s in scripts:
    m = first[s]
    expect_missing(s, [python, "-S", "-I", os.path.join(source, "scripts", s + ".py"), "in.json", "out"], None, m,
                   "python3-" + m)

# numpy present, matplotlib not: a stand-in on PYTHONPATH that fails to import as a missing module would.
with tempfile.TemporaryDirectory() as fake:
    with open(os.path.join(fake, "matplotlib.py"), "w") as f:
        f.write("raise ModuleNotFoundError(\"No module named 'matplotlib'\", name='matplotlib')\n")
    env = dict(os.environ, PYTHONPATH=fake)
    expect_missing("plot_convergence", [python, os.path.join(source, "scripts", "plot_convergence.py"), "a", "b"], env,
                   "matplotlib", "python3-matplotlib")

for s in scripts + ["kerr_field", "mesh_study"]:
    with open(os.path.join(build, "scripts", s + ".py")) as f:
        shebang = f.readline().rstrip("\n")
    if shebang != "#!" + python:
        failures.append(f"build/scripts/{s}.py: shebang '{shebang}', expected '#!{python}'")

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
