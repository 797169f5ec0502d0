#!/usr/bin/env python3
"""include_graph.py [ROOT] — the include graph of conformesh's libraries: edges between concept folders (lib/sub), and
any include cycle between public modules (see below). Exit status 1 when there is one. Standard library only."""
import os, re, subprocess, sys, collections
root = sys.argv[1] if len(sys.argv) > 1 else '.'
os.chdir(root)
def listed():  # the tracked files, or every file when ROOT is not a git checkout
    try: return subprocess.check_output(['git', 'ls-files'], stderr=subprocess.DEVNULL).decode().split()
    except (OSError, subprocess.CalledProcessError):
        return [os.path.relpath(os.path.join(d, f)) for d, _, fs in os.walk('.') for f in fs]
files = [f for f in listed() if re.match(r'(intrinsic|embedding|refine)/.*\.(h|cpp)$', f)]
def key(path):  # file path -> (lib/sub) concept
    m = re.match(r'(\w+)/(?:include/conformesh/\w+|src)/(.*)/[^/]+$', path)
    if m: return m.group(1) + '/' + m.group(2)
    return re.match(r'(\w+)/', path).group(1) + '/(root)'
def resolve(f, inc):
    lib = f.split('/')[0]
    if inc.startswith('conformesh/'):
        l = inc.split('/')[1]; return f'{l}/include/{inc}'
    return f'{lib}/src/{inc}'
edges = collections.Counter(); graph = collections.defaultdict(set)
# a module: a header, its .cpp and its private *_internal.h
norm = lambda p: re.sub(r'(_internal)?\.(h|cpp)$', '', p.replace('/include/conformesh/' + p.split('/')[0], '/src'))
for f in files:
    for inc in re.findall(r'#include\s+"([^"]+)"', open(f).read()):
        t = resolve(f, inc)
        if not os.path.exists(t): continue
        a, b = key(f), key(t)
        if a != b: edges[(a, b)] += 1
        if norm(f) != norm(t): graph[norm(f)].add(norm(t))
for (a, b), n in sorted(edges.items()): print(f'{a:24s} -> {b:24s} {n}')
# Cycles between public modules (a public header and its .cpp). A private file (a header or source under src/ with no
# public header of its name) is part of the public modules whose files include it, directly or through other private
# files: its includes count as theirs. So a private helper that fills its caller's result type is no cycle, and a knot
# between two public modules is one, however many private files it passes through.
public = {norm(f) for f in files if '/include/' in f}
def owners(m, seen=None):
    if m in public: return {m}
    seen = seen or set(); out = set()
    for u, vs in graph.items():
        if m in vs and u not in seen:
            seen.add(u); out |= owners(u, seen)
    return out
def reach(m, seen=None):  # public modules m's files include, through private ones
    seen = seen if seen is not None else set(); out = set()
    for v in graph[m]:
        if v in public: out.add(v)
        elif v not in seen:
            seen.add(v); out |= reach(v, seen)
    return out
mgraph = collections.defaultdict(set)
for m in list(graph):
    for o in owners(m):
        mgraph[o] |= {v for v in reach(m) if v != o}
sys.setrecursionlimit(10000); color = {}; cycles = []
def dfs(u, stack):
    color[u] = 1; stack.append(u)
    for v in sorted(mgraph[u]):
        if color.get(v) == 1: cycles.append(stack[stack.index(v):] + [v])
        elif not color.get(v): dfs(v, stack)
    stack.pop(); color[u] = 2
for u in sorted(mgraph):
    if not color.get(u): dfs(u, [])
print('module include cycles:', len(cycles))
for c in cycles: print('  ' + ' -> '.join(c))
sys.exit(1 if cycles else 0)
