#!/usr/bin/python3
"""test view_chromium: `conformesh view` pages load and draw in headless Chromium (docs/cli.md#view).

usage: view_chromium.py CONFORMESH MESH.off WORKDIR

Two pages — the Kerr a/M = 0.99 horizon (metric-only: drawn on its uniformization's sphere) and MESH remeshed (drawn
on its positions) — are loaded in Debian's chromium with the software GL; for each: the screenshot must show the mesh
(at least 10 % of the canvas region not background white, and at least 50 distinct colours: the field colouring), the
page's own title must say "drawn F triangles" with F the mesh's face count (the title says ERROR if a script failed),
and Chromium's log of the page's console must hold no message other than GL driver performance notes. A deliberately
broken page must fail those checks (so the checks can fail). The PNG is decoded here with zlib only.
"""
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
         "--window-size=800,600"]


def fail(message):
    print("view_chromium: FAILED: " + message)
    sys.exit(1)


def chromium(args):
    exe = shutil.which("chromium")
    if not exe:
        fail("chromium is not installed: apt-get install chromium (scripts/bootstrap.sh installs it)")
    with tempfile.TemporaryDirectory() as profile:
        r = subprocess.run([exe] + FLAGS + ["--user-data-dir=" + profile] + args, capture_output=True, text=True,
                           timeout=120)
    return r


def decode_png(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA PNG, filters 0-4 undone."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + " is not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                fail("unexpected PNG format depth %d colour type %d" % (depth, colour))
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def check_page(page, faces, expect_ok=True):
    """Returns a list of what is wrong with the page as drawn (empty: fine)."""
    problems = []
    shot = page + ".png"
    r = chromium(["--enable-logging=stderr", "--v=0", "--screenshot=" + shot, "file://" + page])
    console = [l for l in r.stderr.splitlines() if ":CONSOLE" in l and "GL Driver Message" not in l]
    if console:
        problems.append("console messages: " + " | ".join(console))
    if not os.path.exists(shot):
        return problems + ["no screenshot (chromium status %d): %s" % (r.returncode, r.stderr[-500:])]
    width, height, rows = decode_png(shot)
    if (width, height) != (800, 600):
        problems.append("screenshot is %dx%d, expected 800x600" % (width, height))
    # The canvas region: left of the 290-pixel panel, above the domain caption.
    region = [px for row in rows[20:540] for px in row[20:480]]
    drawn = sum(1 for px in region if px != (255, 255, 255))
    colours = len(set(region))
    if drawn < 0.10 * len(region) or colours < 50:
        problems.append("canvas region: %d of %d pixels drawn, %d colours (need 10 %%, 50)" %
                        (drawn, len(region), colours))
    dom = chromium(["--dump-dom", "file://" + page]).stdout
    title = re.search(r"<title>([^<]*)</title>", dom)
    want = "conformesh view: drawn %d triangles" % faces
    if not title or title.group(1) != want:
        problems.append("title %r, expected %r" % (title.group(1) if title else None, want))
    print("%s: %d of %d canvas pixels drawn, %d colours, title %r, %d console lines" %
          (os.path.basename(page), drawn, len(region), colours, title.group(1) if title else None, len(console)))
    return problems


def main():
    conformesh, mesh, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    cases = [("kerr", ["remesh", "kerr-newman", "--param", "a=0.99", "--eps", "0.1"]),
             ("eight", ["remesh", mesh, "--eps", "0.05"])]
    for name, command in cases:
        ply, report, page = (os.path.join(work, name + ext) for ext in (".ply", ".json", ".html"))
        with open(report, "w") as out:
            subprocess.run([conformesh, "-q"] + command + ["-o", ply, "--json"], stdout=out, check=True)
        view = subprocess.run([conformesh, "-q", "view", ply, "-o", page, "--report", report, "--json"],
                              capture_output=True, text=True, check=True)
        faces = int(re.search(r'"faces": (\d+)', view.stdout).group(1))
        problems = check_page(page, faces)
        if problems:
            fail(name + ": " + "; ".join(problems))
    # The checks must be able to fail: a page whose script throws draws nothing and says so.
    broken = os.path.join(work, "broken.html")
    with open(os.path.join(work, "eight.html")) as f:
        text = f.read()
    with open(broken, "w") as f:
        f.write(text.replace("var mesh = new THREE.Mesh(", "var mesh = new THREE.NoSuchMesh(", 1))
    problems = check_page(broken, faces)
    if len(problems) < 2:
        fail("a broken page passed the checks: %s" % problems)
    print("broken page rejected: " + "; ".join(p[:80] for p in problems))
    print("view_chromium: passed")


if __name__ == "__main__":
    main()
